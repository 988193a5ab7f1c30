// The feature extractor shared by the actor and the critic (spec README, "PPO agent"):
// observation [B, 6 + 180 S] -> features [B, 6 + S P] = [navigation (6 values, passed through),
// perception encoding of each of the S range scans of 180 closeness values (P = 12 for the paper's
// extractors)]. S = 1 is the paper's observation [B, 186]; S > 1 appends the environment's earlier
// scans (frame stacking), each encoded by the same perception stack.
//
// The perception encoder is a stack of circular Conv1d layers (ReLU between consecutive ones),
// optionally followed by a Linear head:
//   baseline     one circular Conv1d 1->1 (k45, s15, p15), PyTorch's default init, trained from
//                scratch, no activation (reference-learning 6.2, RadarCNN);
//   vae-shallow  the pre-trained VAE encoder's mu (conv stack + fc_mu), deterministic, with the
//   vae-deep     encoder's own weights; locked (frozen, excluded from the optimiser) or unlocked.
//                With head "reference", fc_mu is re-drawn orthogonal (gain sqrt 2, bias 0) and
//                followed by a ReLU: what the authors' agents really used (reference-learning
//                6.2: SB3's orthogonal initialisation overwrote the pre-trained fc_mu).
// The layers are kept as a plain list so the hand-written fast path (actor_critic_fast.h) and
// the TorchScript export (policy_export.h) can mirror them.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "models/vae_architecture.h"

namespace colav {

enum class ExtractorKind { kBaseline, kVaeShallow, kVaeDeep };

/// "baseline", "vae-shallow" or "vae-deep"; anything else is a UserError naming the value.
ExtractorKind ParseExtractorKind(const std::string& name);
std::string ExtractorKindName(ExtractorKind kind);

/// The last layer of a VAE extractor.
enum class EncoderHead {
  kMu,         ///< the pre-trained fc_mu, no activation (the paper's description)
  kReference,  ///< fc_mu re-drawn orthogonal x sqrt 2, bias 0, then ReLU (the authors' agents)
};

/// "mu" or "reference"; anything else is a UserError naming the value.
EncoderHead ParseEncoderHead(const std::string& name);
std::string EncoderHeadName(EncoderHead head);

/// Parses a conv stack "out:kernel:stride:padding[,out:kernel:stride:padding...]" (input channels
/// follow from the previous layer, the first takes 1). A malformed spec is a UserError.
std::vector<ConvLayerSpec> ParseConvStack(const std::string& spec);
/// The inverse of ParseConvStack.
std::string ConvStackText(const std::vector<ConvLayerSpec>& layers);

struct FeatureExtractorOptions {
  ExtractorKind kind = ExtractorKind::kBaseline;
  /// vae-*: the encoder.pt written by train_vae. Empty: the encoder's structure with untrained
  /// weights, for a model whose weights come from a checkpoint.
  std::filesystem::path encoder;
  /// vae-*: frozen (requires_grad false) or fine-tuned with the policy. The baseline always trains.
  bool locked = true;
  /// vae-*: the latent size the encoder file must have.
  std::int64_t latent_dims = 12;
  /// vae-*: the head after the conv stack. The re-drawn weights of kReference come from the
  /// actor-critic's initialisation (actor_critic.h).
  EncoderHead head = EncoderHead::kMu;
  /// baseline: its convolution stack (the paper's: one layer 1->1, k45, s15, p15).
  std::vector<ConvLayerSpec> baseline_convs = {{1, 1, 45, 15, 15}};
  /// Range scans per observation (the environment's scan history + 1); each is encoded by the
  /// same perception stack (shared weights) and the encodings are concatenated.
  std::int64_t scans = 1;
};

/// One layer of the perception encoder: a circular Conv1d or (after flattening) a Linear.
struct PerceptionLayer {
  torch::nn::Conv1d conv{nullptr};
  torch::nn::Linear linear{nullptr};
  bool relu = false;  ///< ReLU after the layer
};

class FeatureExtractorImpl : public torch::nn::Module {
 public:
  explicit FeatureExtractorImpl(FeatureExtractorOptions options);

  /// observations [B, observation_size()] -> features [B, features_dim()]: the navigation values,
  /// then the perception encodings of scans 0, 1, ... in order.
  torch::Tensor forward(const torch::Tensor& observations);
  /// closeness [B, 180] -> perception encoding [B, perception_dims()].
  torch::Tensor Perception(const torch::Tensor& closeness);

  std::int64_t perception_dims() const { return perception_dims_; }
  /// 6 + scans * perception_dims().
  std::int64_t features_dim() const;
  /// Values per observation: 6 navigation values, then scans x 180 closeness values.
  std::int64_t observation_size() const;
  /// False for a locked VAE encoder: its parameters get no gradient and no optimiser.
  bool trainable() const;
  const FeatureExtractorOptions& options() const { return options_; }
  const std::vector<PerceptionLayer>& layers() const { return layers_; }

 private:
  void BuildConvs(const std::vector<ConvLayerSpec>& convs);
  void LoadPretrainedEncoder();

  FeatureExtractorOptions options_;
  torch::nn::ModuleList perception_;
  std::vector<PerceptionLayer> layers_;
  std::int64_t perception_dims_ = 0;
};
TORCH_MODULE(FeatureExtractor);

}  // namespace colav

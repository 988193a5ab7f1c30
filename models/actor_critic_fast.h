// Hand-written forward and backward passes of an ActorCritic, on the model's own parameters.
//
// PPO needs ~375,000 minibatch updates of 32 samples and ~375,000 batched forward passes of 8
// observations per 3M-step run; through LibTorch's autograd these tiny networks cost ~2.8 ms per
// update (per-operator overhead), through these passes ~0.1 ms (measurements in the README). The
// model stays the single source of truth: the passes read its parameter tensors (so checkpoints,
// exports and the optimiser see one set of weights) and write gradients into tensors aligned with
// ActorCritic::TrainableParameters(). tests/models/actor_critic_fast_test.cpp checks both passes
// against autograd.
//
// Activations are feature-major ([features, B], see actor_critic_kernels.h). An observation of S
// range scans runs the perception stack on S * B samples (column k * B + b holds scan k of sample
// b), whose encodings become feature rows 6 + k * P + p. A privileged critic's trunk reads the
// rows it would read otherwise followed by the critic observation's (SetCriticObservations); its
// input gradient reaches the extractor and memory through the former only.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "models/actor_critic.h"
#include "models/actor_critic_kernels.h"
#include "models/recurrent_fast.h"

namespace colav {

/// One layer of a hand-written network: a Linear or a circular Conv1d, then an activation.
struct FastLayer {
  enum class Kind { kLinear, kConv };
  enum class Activation { kNone, kTanh, kRelu };
  Kind kind = Kind::kLinear;
  Activation activation = Activation::kNone;
  torch::Tensor weight, bias;
  torch::Tensor weight_grad, bias_grad;  ///< undefined for a frozen layer
  int in_size = 0;                       ///< values per sample in (conv: channels x length)
  int out_size = 0;
  kernels::CircularConvShape conv{};  ///< kConv only
};

/// A sequence of FastLayers with its activation buffers, for batches up to max_batch.
class FastLayerStack {
 public:
  FastLayerStack(std::vector<FastLayer> layers, int max_batch);

  /// input [in_size, B] -> output [out_size, B] (valid until the next Forward).
  const float* Forward(const float* input, int B);
  /// Backward of the last Forward: d_output [out_size, B] (overwritten) -> layer gradients, and
  /// d_input [in_size, B] unless it is null.
  void Backward(const float* input, float* d_output, int B, float* d_input);

  int in_size() const { return layers_.front().in_size; }
  int out_size() const { return layers_.back().out_size; }

 private:
  std::vector<FastLayer> layers_;
  std::vector<std::vector<float>> outputs_;
  std::vector<float> gradient_a_, gradient_b_, transposed_;
};

class FastActorCritic {
 public:
  /// Binds to `model` (whose parameters must be contiguous float32 CPU tensors) for batches of up
  /// to max_batch samples.
  FastActorCritic(ActorCritic model, int max_batch);

  /// observations [B, observation_size] (row-major) -> action mean [B, 2] and value [B]
  /// (row-major). A recurrent model also takes `states` [B, state_size] (row-major), the states
  /// before these observations, and replaces them by the states after; a privileged critic
  /// `critic_observations` [B, critic_observation_size] (row-major).
  void Predict(const float* observations, int B, float* mean, float* value, float* states = nullptr,
               const float* critic_observations = nullptr);
  /// Extractor output of `count` observations [count, observation_size] -> features
  /// [count, features_dim] (row-major); any count.
  void Features(const float* observations, int count, float* features);

  /// For a recurrent model, before a training forward: its B samples are `sequences` sequences
  /// of B / sequences consecutive steps, in time-major order (sample t * sequences + s is step t of
  /// sequence s); initial_states[s] points to the state (state_size values) before step 0 of
  /// sequence s; reset[t * sequences + s] != 0 where an episode starts (its state is 0 there).
  /// The pointers must stay valid until the backward.
  void SetSequences(const float* const* initial_states, const std::uint8_t* reset, int sequences);

  /// For a privileged critic, before a training forward: rows[b] points to sample b's critic
  /// observation (critic_observation_size values). The pointers must stay valid until the
  /// backward.
  void SetCriticObservations(const float* const* rows);

  /// Training forward of the B samples whose observation rows (length observation_size) are
  /// `rows`.
  void ForwardObservations(const float* const* rows, int B);
  /// Training forward from precomputed feature rows (length features_dim), for an extractor that
  /// does not train.
  void ForwardFeatures(const float* const* rows, int B);
  /// Of the last training forward: action mean [2, B] and value [B] (feature-major).
  const float* mean() const { return mean_; }
  const float* value() const { return value_; }

  /// Backward of the last training forward from the loss gradients d_mean [2, B], d_value [B]
  /// (both overwritten) and d_log_std [2]: writes gradients().
  void Backward(float* d_mean, float* d_value, const float* d_log_std, int B);

  /// Gradient tensors, one per ActorCritic::TrainableParameters() entry, same order and shapes.
  const std::vector<torch::Tensor>& gradients() const { return gradients_; }
  const std::vector<torch::Tensor>& parameters() const { return parameters_; }
  bool extractor_trainable() const { return extractor_trainable_; }
  int features_dim() const { return features_dim_; }
  /// Values per observation row: 6 navigation values, then scans x 180 closeness values.
  int observation_size() const { return observation_size_; }
  const float* log_std() const { return log_std_.data_ptr<float>(); }
  /// Whether the environment gets tanh of the sampled actions (ActorCriticOptions::squash_actions).
  bool squash_actions() const { return model_->options().squash_actions; }
  /// The GRU state's size; 0 for a memoryless model.
  int recurrent_size() const { return static_cast<int>(model_->options().recurrent_size); }
  /// Values of a step's state (ActorCriticOptions::state_size).
  int state_size() const { return static_cast<int>(model_->options().state_size()); }
  /// Values of a sample's critic observation; 0 unless the critic is privileged.
  int critic_observation_size() const { return critic_observation_size_; }

 private:
  void ForwardExtractor(const float* const* rows, int B);
  void ForwardFromFeatures(int B);
  /// The actor's input of the last forward: features_, or [features; GRU states] when recurrent.
  const float* TrunkInput() const { return gru_ ? trunk_input_.data() : features_.data(); }
  /// The critic's: the actor's, or [features; its own GRU's states]; a privileged critic's is
  /// that followed by its critic observations.
  const float* CriticTrunkInput() const {
    return critic_gru_ || critic_observation_size_ > 0 ? critic_trunk_input_.data() : TrunkInput();
  }
  /// critic_trunk_input_ = [what the critic reads otherwise; the rows of SetCriticObservations].
  void GatherCriticObservations(int B);
  void ForwardRecurrent(int B);
  void ForwardMemory(FastGru& gru, const float* initial, int B, float* trunk_input);
  void BackwardMemory(FastGru& gru, float* d_trunk, float* d_features, int B);
  torch::Tensor GradientOf(const torch::Tensor& parameter) const;
  FastLayer Bind(FastLayer::Kind kind, const torch::Tensor& weight, const torch::Tensor& bias,
                 FastLayer::Activation activation) const;

  ActorCritic model_;
  int max_batch_;
  int features_dim_;
  int scans_;
  int observation_size_;
  int critic_observation_size_;
  bool extractor_trainable_;
  std::vector<torch::Tensor> parameters_;
  std::vector<torch::Tensor> gradients_;
  torch::Tensor log_std_, log_std_grad_;
  FastLayerStack perception_, actor_, critic_;
  std::vector<const float*> rows_;             // observation rows of Predict and Features
  std::vector<float> perception_input_;        // [180, scans * B]
  std::vector<float> features_;                // [features_dim, B]
  std::vector<float> trunk_input_;             // [features_dim + recurrent_size, B], recurrent only
  std::vector<float> critic_trunk_input_;      // separate critic memory or privileged critic only
  const float* const* critic_rows_ = nullptr;  // SetCriticObservations'
  std::vector<const float*> predict_critic_rows_;            // Predict's
  std::vector<float> d_features_actor_, d_features_critic_;  // [trunk input width, B]
  std::vector<float> d_perception_;                          // [P, scans * B], for scans > 1
  std::optional<FastGru> gru_;                               ///< recurrent models only
  std::optional<FastGru> critic_gru_;                        ///< separate critic memory only
  // The sequences of the next training forward (SetSequences), and their initial states
  // [state_size, sequences] (the critic's GRU's from row recurrent_size).
  const float* const* initial_states_ = nullptr;
  const std::uint8_t* reset_ = nullptr;
  int sequences_ = 0;
  std::vector<float> initial_states_columns_;
  std::vector<const float*> state_rows_;  // Predict's states
  std::vector<float> d_gru_input_;        // [features_dim, B]
  const float* mean_ = nullptr;
  const float* value_ = nullptr;
};

}  // namespace colav

// ShallowConvVAE / DeepConvVAE: encoder, reparameterised sample, decoder.
#pragma once

#include <torch/torch.h>

#include <cstdint>

#include "models/cptc.h"
#include "models/vae_architecture.h"
#include "models/vae_decoder.h"
#include "models/vae_encoder.h"

namespace colav {

struct VaeOptions {
  VaeArchitecture architecture = VaeArchitecture::kShallow;
  std::int64_t latent_dims = 12;
  DecoderPadding decoder_padding = DecoderPadding::kCircular;
};

class ConvVaeImpl : public torch::nn::Module {
 public:
  explicit ConvVaeImpl(VaeOptions options);

  struct Output {
    torch::Tensor reconstruction;  // [B, 180] in (0, 1)
    torch::Tensor mu;              // [B, latent]
    torch::Tensor logvar;          // [B, latent]
  };

  // Encodes x [B, 180], samples z = mu + eps * exp(logvar / 2) with eps ~ N(0, 1), and decodes z.
  // It samples in training and evaluation alike, as the paper's test error does. eps comes from
  // `generator` (reproducible per seed, independent of other threads).
  Output forward(const torch::Tensor& x, torch::Generator generator);

  VaeEncoder encoder() const { return encoder_; }
  VaeDecoder decoder() const { return decoder_; }
  const VaeOptions& options() const { return options_; }

 private:
  VaeOptions options_;
  VaeEncoder encoder_{nullptr};
  VaeDecoder decoder_{nullptr};
};
TORCH_MODULE(ConvVae);

}  // namespace colav

// The VAE's decoder p(x | z): Linear(latent -> 12) + ReLU, the encoder's convolutions transposed
// (CPTC-1D, or zero padding for the comparison figure), and a sigmoid onto closeness in (0, 1).
#pragma once

#include <torch/torch.h>

#include <cstdint>

#include "models/cptc.h"
#include "models/vae_architecture.h"

namespace colav {

struct VaeDecoderOptions {
  VaeArchitecture architecture = VaeArchitecture::kShallow;
  std::int64_t latent_dims = 12;
  DecoderPadding padding = DecoderPadding::kCircular;
};

class VaeDecoderImpl : public torch::nn::Module {
 public:
  explicit VaeDecoderImpl(VaeDecoderOptions options);

  // z [B, latent] -> reconstruction [B, 180] in (0, 1).
  torch::Tensor forward(const torch::Tensor& z);

  const VaeDecoderOptions& options() const { return options_; }

 private:
  VaeDecoderOptions options_;
  torch::nn::Linear fc_{nullptr};
  torch::nn::ModuleList deconvs_;  // CircularConvTranspose1d
};
TORCH_MODULE(VaeDecoder);

}  // namespace colav

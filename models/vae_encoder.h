// The VAE's encoder q(z | x): a circular Conv1d stack (Shallow or Deep) and two Linear heads for
// the posterior mean and log-variance.
//
// The heads have no ReLU, unlike the reference code: a ReLU on logvar pins the posterior variance
// at >= 1 (spec README, "encoder"; reference-learning 1.7).
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <utility>

#include "models/circular_conv.h"
#include "models/vae_architecture.h"

namespace colav {

struct VaeEncoderOptions {
  VaeArchitecture architecture = VaeArchitecture::kShallow;
  std::int64_t latent_dims = 12;
};

class VaeEncoderImpl : public torch::nn::Module {
 public:
  explicit VaeEncoderImpl(VaeEncoderOptions options);

  // x [B, 180] closeness -> (mu [B, latent], logvar [B, latent]).
  std::pair<torch::Tensor, torch::Tensor> forward(const torch::Tensor& x);
  // The posterior mean alone: the deterministic encoding the agent's feature extractor uses.
  torch::Tensor Mu(const torch::Tensor& x);
  // The convolution stack's output, flattened: x [B, 180] -> [B, 12].
  torch::Tensor Features(const torch::Tensor& x);

  const VaeEncoderOptions& options() const { return options_; }

 private:
  VaeEncoderOptions options_;
  torch::nn::ModuleList convs_;  // CircularConv1d
  torch::nn::Linear fc_mu_{nullptr};
  torch::nn::Linear fc_logvar_{nullptr};
};
TORCH_MODULE(VaeEncoder);

}  // namespace colav

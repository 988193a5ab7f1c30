// The VAE objective (negative beta-ELBO) and the diagnostics built from its terms.
//
// BCE is summed over the 180 values of a scan and KL over the latent dimensions, so the per-sample
// total is the paper's "test error" (42.67 for Shallow). The BCE clamps each log term at -100 as
// PyTorch does, and accepts targets slightly outside [0, 1] (training noise).
#pragma once

#include <torch/torch.h>

#include <cstdint>

#include "models/conv_vae.h"

namespace colav {

// Scalars for the batch version, [B] tensors for the per-sample version. The components are
// reported without beta.
struct VaeLoss {
  torch::Tensor total;  // bce + beta * kl
  torch::Tensor bce;
  torch::Tensor kl;
};

// Training objective: both terms averaged over the batch.
VaeLoss ComputeVaeLoss(const ConvVaeImpl::Output& output, const torch::Tensor& target, double beta);
// The same terms for each sample of the batch: the test error is the mean of `total` over the
// test set.
VaeLoss ComputePerSampleVaeLoss(const ConvVaeImpl::Output& output, const torch::Tensor& target,
                                double beta);

// KL(N(mu, exp(logvar)) || N(0, 1)) of each latent entry: [B, latent].
torch::Tensor KlDivergence(const torch::Tensor& mu, const torch::Tensor& logvar);
// KL of each latent dimension averaged over the batch: [latent].
torch::Tensor KlPerLatentDimension(const torch::Tensor& mu, const torch::Tensor& logvar);

// A latent dimension is active when its average KL exceeds this many nats; below it the posterior
// has collapsed onto the prior and the dimension carries no information.
constexpr double kActiveLatentKlThreshold = 0.01;
std::int64_t CountActiveLatentDimensions(const torch::Tensor& kl_per_dimension,
                                         double threshold = kActiveLatentKlThreshold);

}  // namespace colav

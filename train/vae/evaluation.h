// Evaluation of a VAE on a split, as the paper's test error: per-sample BCE summed over the 180
// values plus beta * KL summed over the latent dimensions, with one sampled z per scan, averaged
// over the scans. Computed in large batches without autograd; the result does not depend on the
// batch size except through the random z.
#pragma once

#include <torch/torch.h>

#include <cstdint>

#include "models/conv_vae.h"

namespace colav {

struct VaeEvaluation {
  double total = 0.0;                  ///< mean per-sample bce + beta * kl
  double bce = 0.0;                    ///< mean per-sample BCE (summed over the scan)
  double kl = 0.0;                     ///< mean per-sample KL (summed over the latent)
  torch::Tensor kl_per_dimension;      ///< [latent] mean KL of each latent dimension
  std::int64_t active_dimensions = 0;  ///< dimensions whose mean KL exceeds 0.01 nats
};

/// Evaluates `model` on x [n, 180]; z samples come from a generator seeded with `seed`.
VaeEvaluation EvaluateVae(ConvVae& model, const torch::Tensor& x, double beta, std::uint64_t seed,
                          std::int64_t batch_size);

}  // namespace colav

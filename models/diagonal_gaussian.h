// The policy's action distribution: a diagonal Gaussian with a state-independent log standard
// deviation (Stable-Baselines3's DiagGaussianDistribution), no squashing; actions are clipped to
// [-1, 1] only at the environment boundary.
#pragma once

#include <torch/torch.h>

namespace colav {

struct DiagonalGaussian {
  torch::Tensor mean;     ///< [B, D]
  torch::Tensor log_std;  ///< [D], shared by every sample

  /// Log-density of actions [B, D], summed over the D dimensions: [B].
  torch::Tensor LogProb(const torch::Tensor& actions) const;
  /// Closed-form entropy, summed over the dimensions: [B].
  torch::Tensor Entropy() const;
  /// mean + std * N(0, 1) noise drawn from `generator`: [B, D].
  torch::Tensor Sample(torch::Generator& generator) const;
};

}  // namespace colav

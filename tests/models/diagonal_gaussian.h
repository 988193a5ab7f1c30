// The policy's action distribution written with tensor operations: a diagonal Gaussian with a
// state-independent log standard deviation (Stable-Baselines3's DiagGaussianDistribution), no
// squashing here (tests/train/ppo/reference_ppo_loss.h has the tanh-squashed distribution's
// entropy); actions are clipped or squashed only at the environment boundary. The reference the
// hand-written rollout and loss kernels (models/actor_critic_fast.h, train/ppo/loss.h) are tested
// against.
#pragma once

#include <torch/torch.h>

#include <cmath>

namespace colav {

struct DiagonalGaussian {
  // log(sqrt(2 pi)), the normalising constant of a unit Gaussian's log-density.
  static double LogSqrtTwoPi() { return 0.5 * std::log(2.0 * M_PI); }

  torch::Tensor mean;     ///< [B, D]
  torch::Tensor log_std;  ///< [D], shared by every sample

  /// Log-density of actions [B, D], summed over the D dimensions: [B].
  torch::Tensor LogProb(const torch::Tensor& actions) const {
    const torch::Tensor z = (actions - mean) * torch::exp(-log_std);
    return (-0.5 * z.square() - log_std - LogSqrtTwoPi()).sum(-1);
  }
  /// Closed-form entropy, summed over the dimensions: [B].
  torch::Tensor Entropy() const {
    return (0.5 + LogSqrtTwoPi() + log_std).sum(-1).expand({mean.size(0)});
  }
  /// mean + std * N(0, 1) noise drawn from `generator`: [B, D].
  torch::Tensor Sample(torch::Generator& generator) const {
    return mean + torch::exp(log_std) * torch::randn(mean.sizes(), generator, mean.options());
  }
};

}  // namespace colav

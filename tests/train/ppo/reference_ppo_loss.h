// PPO's clipped-surrogate loss (train/ppo/loss.h) with autograd: the reference PpoLossGradients'
// closed-form gradients are checked against.
#pragma once

#include <torch/torch.h>

#include "tests/models/diagonal_gaussian.h"
#include "train/ppo/loss.h"

namespace colav {

struct PpoLossResult {
  torch::Tensor loss;  ///< scalar, differentiable
  PpoLossStats stats;
};

/// The entropy of tanh(u), u ~ N(mean, std), estimated on the samples `actions` (= u), each
/// reparametrised as mean + std * eps with eps fixed (train/ppo/loss.h): [B].
inline torch::Tensor SquashedEntropy(const DiagonalGaussian& distribution,
                                     const torch::Tensor& actions) {
  const torch::Tensor std = torch::exp(distribution.log_std);
  const torch::Tensor eps = ((actions - distribution.mean) / std).detach();
  const torch::Tensor u = distribution.mean + std * eps;
  return distribution.Entropy() + torch::log(1 - torch::tanh(u).square()).sum(-1);
}

/// The loss of a minibatch from the current policy's distribution, values [B] (or [B, 1]), and the
/// minibatch's actions [B, 2], old log-probabilities, advantages and returns [B].
inline PpoLossResult PpoLoss(const DiagonalGaussian& distribution, const torch::Tensor& values,
                             const torch::Tensor& actions, const torch::Tensor& old_log_probs,
                             const torch::Tensor& advantages, const torch::Tensor& returns,
                             const PpoLossOptions& options) {
  torch::Tensor normalized = advantages;
  if (options.normalize_advantage && advantages.numel() > 1) {
    normalized = (advantages - advantages.mean()) / (advantages.std() + 1e-8);  // SB3's guard
  }
  const torch::Tensor log_ratio = distribution.LogProb(actions) - old_log_probs;
  const torch::Tensor ratio = torch::exp(log_ratio);
  const torch::Tensor clipped_ratio =
      torch::clamp(ratio, 1.0 - options.clip_range, 1.0 + options.clip_range);
  const torch::Tensor policy_loss =
      -torch::min(normalized * ratio, normalized * clipped_ratio).mean();
  const torch::Tensor value_loss = torch::mse_loss(returns, values.flatten());
  const torch::Tensor entropy_loss =
      -(options.squashed_actions ? SquashedEntropy(distribution, actions) : distribution.Entropy())
           .mean();
  PpoLossResult result;
  result.loss = policy_loss + options.ent_coef * entropy_loss + options.vf_coef * value_loss;
  torch::NoGradGuard no_grad;
  result.stats.loss = result.loss.item<double>();
  result.stats.policy_gradient_loss = policy_loss.item<double>();
  result.stats.value_loss = value_loss.item<double>();
  result.stats.entropy_loss = entropy_loss.item<double>();
  result.stats.approx_kl = ((ratio - 1) - log_ratio).mean().item<double>();
  result.stats.clip_fraction =
      ((ratio - 1).abs() > options.clip_range).to(torch::kFloat64).mean().item<double>();
  return result;
}

}  // namespace colav

// PPO's clipped-surrogate loss with Stable-Baselines3 semantics (reference-learning 6.4):
//   A' = (A - mean A) / (std A + 1e-8)            per minibatch (unbiased std), if normalising
//   r  = exp(log pi(a|s) - log pi_old(a|s))
//   L  = -mean(min(r A', clip(r, 1 - c, 1 + c) A')) + ent_coef * (-mean entropy)
//        + vf_coef * mean((returns - V)^2)
// The entropy is the Gaussian's, sum_j (1/2 + log sqrt(2 pi) + log std_j). For tanh-squashed
// actions (squashed_actions) it is that of tanh(u), u ~ N(mean, std), which has no closed form:
//   H = Gaussian entropy + E[sum_j log(1 - tanh(u_j)^2)],
// estimated on the minibatch's stored samples u, reparametrised as u = mean + std * eps with eps
// held fixed, so that its gradients are d/d mean = -2 tanh(u), d/d log std = -2 tanh(u) (u - mean).
// For mean 0 it is largest near std 0.87 and falls as the std grows (tanh piles the samples at
// +-1), so the bonus no longer widens the std without end. (SB3 estimates it by -mean
// log-probability of the stored actions, whose gradient vanishes at the old policy.)
// PpoLossGradients gives the loss with its gradients in closed form for the hand-written backward
// pass (FastActorCritic); the tests check it against an autograd reference
// (tests/train/ppo/reference_ppo_loss.h).
#pragma once

namespace colav {

struct PpoLossOptions {
  double clip_range = 0.2;
  double ent_coef = 0.01;
  double vf_coef = 0.5;
  bool normalize_advantage = true;
  /// Actions are tanh of the Gaussian samples: the entropy term is the squashed distribution's.
  bool squashed_actions = false;
};

/// One minibatch's loss terms, named as SB3 logs them.
struct PpoLossStats {
  double loss = 0.0;
  double policy_gradient_loss = 0.0;
  double value_loss = 0.0;
  double entropy_loss = 0.0;   ///< -mean entropy (squashed: its minibatch estimate)
  double approx_kl = 0.0;      ///< mean((r - 1) - log r)
  double clip_fraction = 0.0;  ///< fraction of samples with |r - 1| > clip_range
};

/// A minibatch of B samples in flat arrays.
struct PpoMinibatch {
  int size = 0;
  const float* actions = nullptr;        ///< [B, 2], unclipped samples
  const float* old_log_probs = nullptr;  ///< [B]
  const float* advantages = nullptr;     ///< [B], not normalised
  const float* returns = nullptr;        ///< [B]
};

/// Closed-form version: from the policy's mean [2, B] (feature-major), log_std [2] and value [B],
/// writes d loss / d mean [2, B], d loss / d log_std [2] and d loss / d value [B].
PpoLossStats PpoLossGradients(const float* mean, const float* log_std, const float* value,
                              const PpoMinibatch& batch, const PpoLossOptions& options,
                              float* d_mean, float* d_log_std, float* d_value);

}  // namespace colav

// Reward scaling by the running spread of the discounted return: Stable-Baselines3's
// VecNormalize(norm_obs=False, norm_reward=True) and Gymnasium's NormalizeReward. Each world keeps
// its discounted return R <- gamma R + r (reset to 0 when its episode ends); the variance of those
// returns over every step so far (one running estimate for all worlds) scales the rewards the
// learner sees, r / sqrt(Var R + 1e-8), clipped to [-10, 10]. The task's reward is unchanged:
// the logs and the evaluation report the environment's own.
//
// Why: the paper's reward gives -1000 for a collision and about +-1 per step, so with gamma 0.999
// the returns reach thousands, the value loss swamps the global gradient-norm clip (0.5) and the
// policy's gradient is scaled down with it.
#pragma once

#include <cstdint>
#include <vector>

#include "train/ppo/running_variance.h"

namespace colav {

/// What a checkpoint records of the scaler (the rollout start's, checkpoint.h).
struct RewardScalingState {
  RunningVariance return_variance;
  std::vector<double> returns;  ///< one per world, discounted, since its episode started
};

class RewardScaler {
 public:
  /// SB3's clip_reward and epsilon.
  static constexpr double kClip = 10.0;
  static constexpr double kEpsilon = 1e-8;

  RewardScaler(int num_envs, double gamma);

  /// Adds this step's rewards [N] to the returns, updates their variance, writes the scaled
  /// rewards [N], and restarts the return of every world whose episode ended (dones [N]).
  void Scale(const float* rewards, const std::uint8_t* dones, float* scaled);

  const RewardScalingState& state() const { return state_; }
  /// Throws std::invalid_argument if `state` holds another number of worlds.
  void Restore(const RewardScalingState& state);
  /// Restarts every world's return, as at the end of its episode (a curriculum's switch).
  void RestartReturns();

 private:
  double gamma_;
  RewardScalingState state_;
};

}  // namespace colav

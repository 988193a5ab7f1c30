// Generalised advantage estimation with Stable-Baselines3 semantics (reference-learning 6.4;
// SB3 RolloutBuffer.compute_returns_and_advantage), on flat [num_steps, num_envs] arrays.
//
// An episode that ends at step t (terminated or truncated) cuts the recursion there. A time-limit
// truncation is not a true end: its reward is bootstrapped with gamma * V(final observation) before
// the recursion, as SB3's collect_rollouts does; which ends are bootstrapped is the rollout's
// decision (train/ppo/rollout.h, BootstrapsFromFinalObservation).
#pragma once

#include <cstdint>

namespace colav {

struct GaeInput {
  int num_steps = 0;
  int num_envs = 0;
  double gamma = 0.999;
  double lambda = 0.98;
  const float* rewards = nullptr;       ///< [T, N]
  const float* values = nullptr;        ///< [T, N]: V of the observation the action was taken in
  const std::uint8_t* dones = nullptr;  ///< [T, N]: the episode ended at this step
  const std::uint8_t* bootstrapped = nullptr;  ///< [T, N]: ... and continues with V(final obs)
  const float* final_values = nullptr;  ///< [T, N]: V(final observation), read where bootstrapped
  const float* last_values = nullptr;   ///< [N]: V of the observation after the last step
};

/// Writes advantages [T, N] and returns [T, N] (= advantages + values).
void ComputeGae(const GaeInput& input, float* advantages, float* returns);

}  // namespace colav

// One PPO rollout: n_steps x n_envs transitions, stored step-major (sample i = t * n_envs + env),
// with SB3's fields (reference-learning 6.3): the observation the action was taken in, the
// unclipped sampled action, its log-probability, the value estimate, the reward, whether the
// episode ended (and by truncation, with the value of its final observation for bootstrapping).
#pragma once

#include <cstdint>
#include <vector>

#include "env/environment_spec.h"

namespace colav {

class RolloutBuffer {
 public:
  /// observation_size: floats per observation row (ObservationSize of the environment);
  /// state_size: the recurrent policy's state size (0: memoryless); critic_observation_size: a
  /// privileged critic's observation size (0: none).
  RolloutBuffer(int num_steps, int num_envs, int observation_size, int state_size = 0,
                int critic_observation_size = 0);

  int num_steps() const { return num_steps_; }
  int num_envs() const { return num_envs_; }
  int size() const { return num_steps_ * num_envs_; }
  int observation_size() const { return observation_size_; }

  // Rows of step t, one per world.
  float* observations(int t) { return &observations_[Offset(t, observation_size_)]; }
  float* actions(int t) { return &actions_[Offset(t, kActionSize)]; }
  float* log_probs(int t) { return &log_probs_[Offset(t, 1)]; }
  float* values(int t) { return &values_[Offset(t, 1)]; }
  float* rewards(int t) { return &rewards_[Offset(t, 1)]; }
  std::uint8_t* dones(int t) { return &dones_[Offset(t, 1)]; }
  std::uint8_t* bootstrapped(int t) { return &bootstrapped_[Offset(t, 1)]; }
  float* final_values(int t) { return &final_values_[Offset(t, 1)]; }
  /// A recurrent policy's state before step t (0 where an episode starts), state_size each.
  float* states(int t) { return states_.data() + Offset(t, state_size_); }
  /// A privileged critic's observation at step t, critic_observation_size each.
  float* critic_observations(int t) {
    return critic_observations_.data() + Offset(t, critic_observation_size_);
  }
  /// V of the observations after the last step, one per world.
  float* last_values() { return last_values_.data(); }

  /// GAE advantages and returns of the filled rollout (gae.h).
  void ComputeReturnsAndAdvantages(double gamma, double lambda);
  /// 1 - Var(returns - values) / Var(returns) over the rollout (NaN if the returns are constant),
  /// SB3's explained_variance.
  double ExplainedVariance() const;

  // Whole-rollout arrays, indexed by sample.
  const std::vector<float>& observations() const { return observations_; }
  const std::vector<float>& actions() const { return actions_; }
  const std::vector<float>& log_probs() const { return log_probs_; }
  const std::vector<float>& values() const { return values_; }
  const std::vector<float>& advantages() const { return advantages_; }
  const std::vector<float>& returns() const { return returns_; }
  const std::vector<float>& states() const { return states_; }
  const std::vector<float>& critic_observations() const { return critic_observations_; }
  const std::vector<std::uint8_t>& dones() const { return dones_; }
  int state_size() const { return state_size_; }
  int critic_observation_size() const { return critic_observation_size_; }

 private:
  std::size_t Offset(int t, int width) const {
    return static_cast<std::size_t>(t) * num_envs_ * width;
  }

  int num_steps_;
  int num_envs_;
  int observation_size_;
  int state_size_;
  int critic_observation_size_;
  std::vector<float> observations_, actions_, log_probs_, values_, rewards_, final_values_;
  std::vector<std::uint8_t> dones_, bootstrapped_;
  std::vector<float> last_values_, advantages_, returns_;
  std::vector<float> states_;
  std::vector<float> critic_observations_;
};

}  // namespace colav

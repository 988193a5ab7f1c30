// Collects PPO rollouts from the batched environment (SB3 collect_rollouts, reference-learning
// 6.3): actions are sampled from the policy's Gaussian, clipped to [-1, 1] (or, for a policy that
// squashes its actions, put through tanh) for the environment only (the buffer keeps the Gaussian
// sample and its Gaussian log-probability: tanh's Jacobian term is the same for the old and the
// new policy at a stored sample, so PPO's probability ratio does not change), a truncated episode's
// final observation is valued for bootstrapping (BootstrapsFromFinalObservation), and optionally
// the rewards are scaled (reward_scaling.h) and the navigation values the policy sees normalised
// (navigation_normalizer.h). A recurrent policy's state is kept per world, recorded in the buffer
// before each step and set to 0 when the world's episode ends.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "env/batched_environment.h"
#include "models/actor_critic_fast.h"
#include "train/ppo/navigation_normalizer.h"
#include "train/ppo/reward_scaling.h"
#include "train/ppo/rollout_buffer.h"

namespace colav {

/// A finished episode, as logged.
struct FinishedEpisode {
  int env = 0;
  std::uint64_t seed = 0;  ///< the scenario's seed
  EpisodeMetrics metrics;
};

/// Whether the return of an episode's last step continues with gamma * V(final observation): only
/// for an episode cut by the step limit. One that also terminated on that step (a collision on its
/// last allowed step) does not, as in Stable-Baselines3's vector environments, whose
/// "TimeLimit.truncated" is truncated and not terminated. With `timeouts_terminal` (the reference
/// training, whose time-outs end episodes like a terminal state) none does.
bool BootstrapsFromFinalObservation(bool terminated, bool truncated, bool timeouts_terminal);

/// How the collector turns environment steps into training samples.
struct RolloutRules {
  bool timeouts_terminal = false;  ///< see BootstrapsFromFinalObservation
  /// Scale the rewards by the spread of the discounted return (reward_scaling.h) with discount
  /// `gamma`; otherwise the buffer holds the environment's rewards.
  bool scale_rewards = false;
  double gamma = 0.0;
  /// Normalise the navigation values of the observations the policy sees and the buffer keeps
  /// (navigation_normalizer.h); the running moments take in each step's new observations, as
  /// SB3's VecNormalize does (not a final observation, which is only normalised).
  bool normalize_navigation = false;
  /// A privileged critic's nearest vessels (ActorCriticOptions::critic_vessels): the worlds also
  /// write their critic observations, which the buffer keeps and the critic reads; 0: none.
  int critic_vessels = 0;
};

class RolloutCollector {
 public:
  /// One world per entry of `world_scenarios`, each playing that training scenario; env_seed
  /// determines every scenario they will play.
  RolloutCollector(const EnvironmentConfig& config,
                   const std::vector<TrainingScenarioConfig>& world_scenarios, int threads,
                   std::uint64_t env_seed, const RolloutRules& rules);

  /// Called after every environment step with the episodes that just ended; returning false stops
  /// the rollout early.
  using StepCallback = std::function<bool(const std::vector<FinishedEpisode>& finished)>;

  /// Fills `buffer` step by step with noise [n_steps, n_envs, 2] of N(0, 1) values (the sampling
  /// noise, drawn by the caller from its generator). Returns false if `after_step` stopped it, in
  /// which case the buffer is incomplete.
  bool Collect(FastActorCritic& policy, const torch::Tensor& noise, RolloutBuffer& buffer,
               const StepCallback& after_step);

  /// What each world has played since its episode started (a checkpoint's record of the worlds).
  const std::vector<WorldHistory>& world_histories() const { return env_->histories(); }
  /// Puts the worlds back where world_histories() left them (BatchedEnvironment::Restore).
  void RestoreWorlds(const std::vector<WorldHistory>& histories);
  /// From now on each world plays its entry of `world_scenarios` (a curriculum's next stage):
  /// every world abandons its episode, unlogged, and starts its next one in its new kind, so
  /// that no episode is played partly in each kind and a resume can rebuild the worlds from
  /// their histories. Their returns for reward scaling restart, as at an episode's end.
  void ReplaceWorlds(const std::vector<TrainingScenarioConfig>& world_scenarios);
  /// The reward scaler's state (a checkpoint's record; unused when rewards are not scaled).
  const RewardScalingState& reward_scaling() const { return reward_scaler_.state(); }
  /// Throws std::invalid_argument if it was recorded for another number of worlds.
  void RestoreRewardScaling(const RewardScalingState& state) { reward_scaler_.Restore(state); }
  /// The running moments of the navigation values (a checkpoint's record; unused when off).
  const NavigationNormalizer::Moments& navigation_moments() const {
    return navigation_normalizer_.moments();
  }
  void RestoreNavigationMoments(const NavigationNormalizer::Moments& moments);
  /// What the policy applies to raw navigation values now; none when they are not normalised.
  std::optional<NavigationNormalization> navigation_normalization() const;
  /// A recurrent policy's state in each world before its current observation, [n_envs, state
  /// size] (a checkpoint's record; empty before the first rollout and for a memoryless policy).
  const std::vector<float>& policy_states() const { return states_; }
  void RestorePolicyStates(const std::vector<float>& states) { states_ = states; }

  /// Wall time spent stepping the worlds so far (s).
  double env_seconds() const { return env_seconds_; }

 private:
  void ValueFinalObservations(FastActorCritic& policy, int t, RolloutBuffer& buffer);
  /// With navigation normalisation, makes the policy's view of the worlds' current observations,
  /// adding them to the navigation moments first if `new_observations` (not when the worlds or
  /// moments are restored); otherwise the policy sees the environment's own.
  void SeeObservations(bool new_observations);
  /// The worlds' current observations as the policy sees them.
  const float* SeenObservations() const;

  EnvironmentConfig config_;
  int threads_;
  std::uint64_t env_seed_;
  RolloutRules rules_;
  std::unique_ptr<BatchedEnvironment> env_;  ///< replaced by ReplaceWorlds
  RewardScaler reward_scaler_;
  NavigationNormalizer navigation_normalizer_;
  std::vector<float> normalized_observations_;  ///< with navigation normalisation only
  std::vector<float> final_observation_;
  std::vector<float> mean_, bounded_actions_, scratch_values_, scratch_means_;
  std::vector<float> states_;          ///< a recurrent policy's, [n_envs, state size]
  std::vector<float> scratch_states_;  ///< states_ copied, for values that must not advance it
  std::vector<FinishedEpisode> finished_;
  double env_seconds_ = 0.0;
};

}  // namespace colav

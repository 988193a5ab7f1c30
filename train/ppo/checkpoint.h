// PPO checkpoints: RUN/policy.pt (TorchScript, policy_export.h), RUN/training_state.pt (a
// torch::serialize archive of the weights, the Adam state, the sampling generator's state and
// the counters), and optionally RUN/checkpoints/policy_<step>.pt; each file is written
// atomically, so an interrupted save leaves the previous checkpoint intact.
//
// A checkpoint can fall inside a rollout (every checkpoint_interval steps, or on SIGKILL the last
// one). The weights and the Adam state do not change within a rollout, so the state file also
// records the start of the rollout in progress (RolloutStart: counters, sampling generator, the
// worlds' histories, the reward scaler, the navigation moments, a recurrent policy's states); a
// resumed run replays that rollout
// and so ends bit for bit where an uninterrupted run does.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "env/batched_environment.h"
#include "env/observation_settings.h"
#include "models/actor_critic.h"
#include "models/adam.h"
#include "train/ppo/navigation_normalizer.h"
#include "train/ppo/reward_scaling.h"

namespace colav {

struct TrainingCounters {
  std::int64_t global_step = 0;  ///< environment steps, all worlds
  std::int64_t n_updates = 0;    ///< epochs of PPO updates (SB3's _n_updates)
  std::int64_t rollouts = 0;
  std::int64_t episodes = 0;
  double wall_s = 0.0;  ///< training wall time, summed over resumed sessions
};

/// Where a resumed run starts: the start of the rollout in progress at the checkpoint (the end
/// of the last one when the checkpoint falls between rollouts).
struct RolloutStart {
  TrainingCounters counters;         ///< wall_s: the training time up to the checkpoint
  torch::Tensor generator_state;     ///< before the rollout's sampling noise was drawn
  std::vector<WorldHistory> worlds;  ///< one per world
  /// The reward scaler's (empty returns in a state file from before reward scaling, which was
  /// then always off).
  RewardScalingState reward_scaling;
  /// The navigation normaliser's (the initial moments in a state file from before it existed).
  NavigationNormalizer::Moments navigation_moments;
  /// A recurrent policy's state in each world, [n_envs * state size] (empty: memoryless, or
  /// before the first rollout; then every state starts at 0).
  std::vector<float> policy_states;
};

/// Path of the training state in a run folder.
std::filesystem::path TrainingStatePath(const std::filesystem::path& run_dir);

/// `settings` are the observation settings the policy is trained with (recorded in policy.pt),
/// `navigation` the normalisation of its navigation values now, if any (exported with it);
/// `resolved_config` (Config::ToJson's text) is recorded in the state file, so that a resumed run
/// is checked against what it was trained with, not against a config.yaml edited since.
void SaveCheckpoint(const std::filesystem::path& run_dir, ActorCriticImpl& model,
                    const Adam& optimizer, torch::Generator& generator,
                    const TrainingCounters& counters, const RolloutStart& rollout_start,
                    const ObservationSettings& settings,
                    const std::optional<NavigationNormalization>& navigation,
                    const std::string& resolved_config, bool keep_policy_copy);

/// The configuration text SaveCheckpoint recorded in run_dir's state file; nullopt for a state
/// file from before it was recorded. A missing or unreadable file is a UserError naming it.
std::optional<std::string> RecordedConfig(const std::filesystem::path& run_dir);

/// Restores the weights and optimiser in place and returns where the run resumes. A missing,
/// truncated or inconsistent state file, or one that does not fit `model`, is a UserError naming
/// it; so is one from before the worlds were saved, which cannot resume exactly.
RolloutStart LoadCheckpoint(const std::filesystem::path& run_dir, ActorCriticImpl& model,
                            Adam& optimizer);

}  // namespace colav

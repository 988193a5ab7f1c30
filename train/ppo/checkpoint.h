// PPO checkpoints: RUN/policy.pt (TorchScript, policy_export.h), RUN/training_state.pt (a
// torch::serialize archive of the weights, the Adam state, the sampling generator's state and
// the counters), and optionally RUN/checkpoints/policy_<step>.pt; each file is written
// atomically, so an interrupted save leaves the previous checkpoint intact.
//
// The worlds' states are not saved: a resumed run starts new episodes (from a seed derived from
// the step count), as an SB3 agent reloaded from a checkpoint does.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <filesystem>

#include "env/observation_settings.h"
#include "models/actor_critic.h"
#include "models/adam.h"

namespace colav {

struct TrainingCounters {
  std::int64_t global_step = 0;  ///< environment steps, all worlds
  std::int64_t n_updates = 0;    ///< epochs of PPO updates (SB3's _n_updates)
  std::int64_t rollouts = 0;
  std::int64_t episodes = 0;
  double wall_s = 0.0;  ///< training wall time, summed over resumed sessions
};

/// Path of the training state in a run folder.
std::filesystem::path TrainingStatePath(const std::filesystem::path& run_dir);

/// `settings` are the observation settings the policy is trained with (recorded in policy.pt).
void SaveCheckpoint(const std::filesystem::path& run_dir, ActorCriticImpl& model,
                    const Adam& optimizer, torch::Generator& generator,
                    const TrainingCounters& counters, const ObservationSettings& settings,
                    bool keep_policy_copy);

/// Restores the weights, optimiser and generator in place. A missing state file, or one that does
/// not fit `model`, is a UserError naming it.
TrainingCounters LoadCheckpoint(const std::filesystem::path& run_dir, ActorCriticImpl& model,
                                Adam& optimizer, torch::Generator& generator);

}  // namespace colav

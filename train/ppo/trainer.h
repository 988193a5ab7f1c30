// PPO training of the collision-avoidance agent (spec README "PPO agent"; Stable-Baselines3
// semantics, reference-learning 6.3-6.5): rollouts of n_steps x n_envs from the batched
// environment, GAE, n_epochs of minibatch updates, checkpoints every checkpoint_interval steps and
// at the end, logs and a summary in the run folder. SIGINT / SIGTERM abandon the rollout in
// progress, write the state to resume from (checkpoint.h) and stop; a resumed run replays that
// rollout and ends bit for bit as an uninterrupted one. A NaN or Inf stops training with
// TrainingDiverged, keeping the last good checkpoint.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "train/ppo/checkpoint.h"
#include "train/ppo/config.h"
#include "train/ppo/logs.h"

namespace colav {

struct PpoRunSummary {
  TrainingCounters counters;  ///< at the end of the session
  std::int64_t session_steps = 0;
  double wall_s = 0.0;        ///< this session
  double steps_per_s = 0.0;   ///< this session
  double rollout_s = 0.0;     ///< of which collecting rollouts ...
  double env_s = 0.0;         ///< ... (of which stepping the worlds)
  double update_s = 0.0;      ///< ... PPO updates
  double checkpoint_s = 0.0;  ///< ... writing checkpoints
  bool finished = false;      ///< reached ppo.total_steps (false: stopped by a signal)
  RollingEpisodeStats rolling;
};

/// The policy a new run of `options` starts from: its own initialisation (a VAE extractor's
/// pre-trained encoder loaded), or policy.init's weights. A bad encoder or policy file is a
/// UserError naming it.
ActorCritic InitialPolicy(const PpoRunOptions& options);

/// Trains the agent configured by `options` in run_dir, from scratch or resuming from its
/// checkpoint, and writes run_dir/summary.json, which records `resolved_config` (Config::ToJson of
/// the configuration the options were read from). Logs what it starts once the files it resumes
/// have been checked (a UserError otherwise). A finished run resumed with its total steps trains
/// nothing: it writes only policy.pt and the configuration in summary.json again (a changed
/// deterministic action). LibTorch's intra-op thread count is the caller's to set (train_ppo
/// runs one).
PpoRunSummary TrainPpo(const PpoRunOptions& options, const nlohmann::json& resolved_config,
                       const std::filesystem::path& run_dir, bool resume);

}  // namespace colav

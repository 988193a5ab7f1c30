// Runs policies on evaluation episodes with deterministic actions, all episodes of all models in
// lock step: one batched forward per model and time step, the worlds stepped in parallel.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "env/environment_spec.h"
#include "eval/evaluation_episodes.h"
#include "eval/policy.h"
#include "eval/replay/replay.h"

namespace colav {

/// What one policy did in one episode.
struct EpisodeOutcome {
  EpisodeMetrics metrics;
  std::vector<Eigen::Vector2d> positions;  ///< vessel position, row 0 = after reset
  std::vector<double> cumulative_rewards;  ///< cumulative reward at each position (0 at reset)
  /// The policy's actions: actions[k] led from positions[k] to positions[k + 1]. The episode is a
  /// pure function of its scenario and these, so they replay it (the collision analysis).
  std::vector<std::array<float, kActionSize>> actions;
  std::optional<Replay> replay;  ///< every step, labelled by the policy's name, if recorded
};

/// outcomes[m][e]: policy m on episode e, in the environment `config` under the policy's own
/// observation settings (those of `config` for a policy that has none). Each time step, a policy's
/// forward (a recurrent policy's step, with each episode's own state, initial at its start) sees
/// the observations of its unfinished episodes (at least two rows), so an episode's result does
/// not depend on the other episodes when the policy's rows are computed independently of the batch
/// size, as LibTorch's CPU kernels do for two rows and more.
/// `on_episode_done(finished, total)` is called from the calling thread after each time step in
/// which episodes finished. With `record_replays`, each outcome holds its episode as a replay.
std::vector<std::vector<EpisodeOutcome>> RunEpisodes(
    std::vector<Policy>& policies, const std::vector<EvaluationEpisode>& episodes,
    const EnvironmentConfig& config, int num_threads,
    const std::function<void(int finished, int total)>& on_episode_done = {},
    bool record_replays = false);

}  // namespace colav

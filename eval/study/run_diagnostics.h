// What each PPO run of a study ended with, read from its folder (train_ppo's outputs): the
// wall-clock it took, its action distribution's standard deviation at the end, and how often its
// training episodes collided and timed out over the last tenth of its steps. The std tells the
// bang-bang regime (far past the action box: actions clipped to a limit) from smooth steering;
// the training rates (sampled actions, training worlds) stand beside the test's deterministic
// ones.
#pragma once

#include <filesystem>

namespace colav {

struct RunDiagnostics {
  double wall_s = 0.0;           ///< summary.json total_wall_s: every session of the run
  double final_std = 0.0;        ///< updates.csv `std` of the last update (mean over the actions)
  int late_episodes = 0;         ///< training episodes ended in the last tenth of the steps
  double late_collisions = 0.0;  ///< % of those that collided
  double late_time_outs = 0.0;   ///< % of those truncated
};

/// The last tenth of a run: episodes ending after this share of its final step.
inline constexpr double kLateShare = 0.9;

/// Reads RUN/summary.json, RUN/updates.csv and RUN/episodes.csv; a missing or malformed file is a
/// UserError naming it.
RunDiagnostics ReadRunDiagnostics(const std::filesystem::path& run);

}  // namespace colav

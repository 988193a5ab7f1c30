// Specification of the collision-avoidance environment: spaces, configuration, episode record.
//
// Kept apart from the implementation (EnvPool style) so learners can size their buffers and
// networks without knowing how the world is simulated.
#pragma once

#include <cstdint>

namespace colav {

/// Rays of the range-finder (2 degrees apart, full circle).
inline constexpr int kNumRays = 180;
/// Navigation features: [u, v, r, cte/100, heading error, look-ahead heading error].
inline constexpr int kNavigationSize = 6;
/// The paper's observation = navigation features (indices 0-5) then 180 closeness values
/// (indices 6-185). With a scan history (EnvironmentConfig::scan_history) earlier scans follow.
inline constexpr int kObservationSize = kNavigationSize + kNumRays;
/// Actions: [thrust in [-1, 1] -> 0..2 N forward, yaw moment in [-1, 1] -> +-0.15 N m].
inline constexpr int kActionSize = 2;

/// How a measured range d (0..150 m) becomes a closeness value in [0, 1].
enum class ClosenessTransform {
  kLinear,  ///< 1 - d/150 (the paper; what the VAE is trained on)
  kLog,     ///< 1 - ln(1+d)/ln(151) (the reference code's environment)
};

struct EnvironmentConfig {
  ClosenessTransform closeness = ClosenessTransform::kLinear;
  /// Test mode switches off the cumulative-reward termination rule (reference test procedure).
  bool test_mode = false;
  /// Episodes are truncated after this many steps.
  std::int64_t max_steps = 2000;
  /// Goal reached within this distance (m) of the path end ...
  double goal_radius = 5.0;
  /// ... or when progress s*/L reaches this value.
  double goal_progress = 0.99;
  /// Training episodes end when the cumulative reward drops below this.
  double min_cumulative_reward = -2000.0;
  /// Earlier range scans appended to the observation, so that a policy can see other vessels
  /// move (frame stacking); 0 is the paper's observation.
  int scan_history = 0;
  /// Steps between two consecutive scans of that history.
  int scan_history_interval = 5;
  /// 0: the range-finder tests every obstacle every step. N > 0: the reference's nearby-obstacle
  /// list (reference-simulator 6.2; 25 in the authors' training): the range-finder sees only the
  /// obstacles within 150 m of the vessel's hull when the list was last rebuilt, at the reset and
  /// every N steps, so one that comes into range in between stays unseen until the next rebuild.
  /// Collisions are checked against every obstacle either way.
  int obstacle_list_refresh = 0;
};

/// Range scans in an observation: the current one, then the history, newest first. Before an
/// episode has run long enough, the missing earlier scans are its first scan.
inline int ScansPerObservation(const EnvironmentConfig& config) { return 1 + config.scan_history; }

/// Floats in an observation: the navigation features, then kNumRays per scan.
inline int ObservationSize(const EnvironmentConfig& config) {
  return kNavigationSize + kNumRays * ScansPerObservation(config);
}

/// Record of a finished episode (reference-simulator 9.1, plus goal reached).
struct EpisodeMetrics {
  double progress = 0.0;      ///< last instantaneous progress s*/L
  double mean_abs_cte = 0.0;  ///< mean |cross-track error| over the steps (m)
  std::int64_t steps = 0;     ///< number of steps taken
  bool collision = false;
  bool goal_reached = false;
  bool truncated = false;  ///< ended by the step limit
  double cumulative_reward = 0.0;
  double path_length = 0.0;  ///< L (m)
};

}  // namespace colav

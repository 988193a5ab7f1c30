// What a replay holds: one scene and, for each model that ran it, the vessel's state after the
// reset and after every step, at the precision the replay file keeps (float32 numbers, one byte
// of closeness per ray), so a replay read back from its file equals the one written.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "env/environment_spec.h"

namespace colav {

struct ReplayPoint {
  float x = 0;
  float y = 0;
};

/// A position and a heading (rad, from the x axis).
struct ReplayPose {
  float x = 0;
  float y = 0;
  float heading = 0;
};

struct ReplayCircle {
  float x = 0;
  float y = 0;
  float radius = 0;
};

/// The vessel and what it sensed after the reset (step 0) or after step k.
struct ReplayStep {
  ReplayPose pose;
  float surge = 0;  ///< u (m/s)
  float sway = 0;   ///< v (m/s)
  float yaw_rate = 0;
  float cross_track_error = 0;
  float heading_error = 0;
  float look_ahead_heading_error = 0;
  float progress = 0;
  ReplayPoint look_ahead_point;
  /// The action that led here, clipped to [-1, 1] as the vessel used it (0 after the reset).
  std::array<float, kActionSize> action{};
  float reward = 0;  ///< the reward of the step that led here
  bool collision = false;
  /// Ray i's range d as round(255 * (1 - d / 150)): 0 = no return, 255 = contact.
  std::array<std::uint8_t, kNumRays> closeness{};
};

/// One model's run through the scene.
struct ReplayRun {
  std::string label;
  std::vector<ReplayStep> steps;  ///< steps[0] = after the reset
};

/// What every run shares: the path, the static obstacles and the moving vessels' hulls, whose
/// motion does not depend on the runs.
struct ReplayScene {
  std::string name;
  std::vector<ReplayPoint> path;  ///< the smoothed path as a polyline
  std::vector<ReplayCircle> circles;
  std::vector<float> vessel_widths;                   ///< moving vessel k's hull width (m)
  std::vector<std::vector<ReplayPose>> vessel_poses;  ///< [step][k], as long as the longest run
};

struct Replay {
  ReplayScene scene;
  std::vector<ReplayRun> runs;
};

/// Closeness byte of a range (m), see ReplayStep::closeness; and the range it stands for.
std::uint8_t ClosenessByte(double range);
double RangeOfClosenessByte(std::uint8_t closeness);

/// Steps of the longest run.
int ReplayLength(const Replay& replay);

}  // namespace colav

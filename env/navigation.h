// Guidance quantities of the vessel relative to the path (reference-simulator 4.3).
#pragma once

#include <Eigen/Core>

#include "env/path.h"

namespace colav {

/// Look-ahead distance along the path for the line-of-sight point (m).
inline constexpr double kLookAheadDistance = 150.0;

struct NavigationState {
  double closest_arclength = 0.0;         ///< s*
  double cross_track_error = 0.0;         ///< m, positive on the right of the path
  double heading_error = 0.0;             ///< rad, line of sight to the look-ahead point
  double look_ahead_heading_error = 0.0;  ///< rad, path tangent at the look-ahead point
  double progress = 0.0;                  ///< s*/L
  double goal_distance = 0.0;             ///< m, to the path end
};

NavigationState Navigate(const Path& path, const Eigen::Vector2d& position, double heading);

}  // namespace colav

#include "env/navigation.h"

#include <algorithm>
#include <cmath>

#include "env/angles.h"

namespace colav {

NavigationState Navigate(const Path& path, const Eigen::Vector2d& position, double heading) {
  NavigationState nav;
  nav.closest_arclength = path.ClosestArclength(position);
  const Eigen::Vector2d closest = path.Point(nav.closest_arclength);
  const double path_direction = path.Direction(nav.closest_arclength);
  // y component of R(-chi) (closest - position).
  nav.cross_track_error = -std::sin(path_direction) * (closest.x() - position.x()) +
                          std::cos(path_direction) * (closest.y() - position.y());
  const double look_ahead_arclength =
      std::min(path.length(), nav.closest_arclength + kLookAheadDistance);
  nav.look_ahead_heading_error = WrapAngle(path.Direction(look_ahead_arclength) - heading);
  const Eigen::Vector2d target = path.Point(look_ahead_arclength);
  nav.heading_error =
      WrapAngle(std::atan2(target.y() - position.y(), target.x() - position.x()) - heading);
  nav.progress = nav.closest_arclength / path.length();
  nav.goal_distance = (path.end() - position).norm();
  return nav;
}

}  // namespace colav

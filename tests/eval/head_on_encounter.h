// The encounter the collision tests share: our vessel at rest at the origin, heading +x along a
// path to (400, 0), and one vessel 10 m wide coming straight at it from `distance` m at `speed`.
#pragma once

#include <cmath>

#include "env/scenario.h"

namespace colav::testing_util {

inline Scenario HeadOnEncounter(double distance, double speed) {
  Scenario scenario;
  scenario.name = "head-on";
  scenario.waypoints = {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(400.0, 0.0)};
  VesselObstacleSpec vessel;
  vessel.position = Eigen::Vector2d(distance, 0.0);
  vessel.width = 10.0;
  vessel.course = M_PI;
  vessel.speed = speed;
  scenario.dynamic_obstacles = {vessel};
  return scenario;
}

}  // namespace colav::testing_util

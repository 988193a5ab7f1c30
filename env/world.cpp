#include "env/world.h"

#include "env/angles.h"

namespace colav {

World::World() : collision_checker_(CybershipModel::kRadius) {}

void World::Load(const Scenario& scenario) {
  path_.emplace(scenario.waypoints);
  vessel_ << scenario.vessel_position, WrapAngle(scenario.vessel_heading), scenario.vessel_velocity;
  static_obstacles_ = scenario.static_obstacles;
  moving_obstacles_.clear();
  for (const VesselObstacleSpec& spec : scenario.dynamic_obstacles) {
    moving_obstacles_.emplace_back(spec);
  }
  hulls_.clear();
  for (const MovingObstacle& obstacle : moving_obstacles_) hulls_.push_back(&obstacle.hull());
  collision_checker_.Load(static_obstacles_, moving_obstacles_);
  Sense();
}

void World::Advance(const GeneralisedForce& tau) {
  for (MovingObstacle& obstacle : moving_obstacles_) obstacle.Advance(kTimeStep);
  vessel_ = CybershipModel::Step(vessel_, tau, kTimeStep);
  Sense();
}

void World::Sense() {
  const Eigen::Vector2d position = vessel_.head<2>();
  navigation_ = Navigate(*path_, position, vessel_[2]);
  range_finder_.Scan(position, vessel_[2], static_obstacles_, hulls_, ranges_.data());
  collision_ = collision_checker_.Collides(position, moving_obstacles_);
}

}  // namespace colav

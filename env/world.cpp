#include "env/world.h"

#include "env/angles.h"

namespace colav {

namespace {

// The reference lists an obstacle when its distance minus the vessel's width is below the
// range-finder's range (reference-simulator 6.2).
constexpr double kListingDistance = RangeFinder::kRange + CybershipModel::kRadius;

}  // namespace

World::World(int obstacle_list_refresh)
    : obstacle_list_refresh_(obstacle_list_refresh), collision_checker_(CybershipModel::kRadius) {}

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
  steps_ = 0;
  Sense();
}

void World::Advance(const GeneralisedForce& tau) {
  for (MovingObstacle& obstacle : moving_obstacles_) obstacle.Advance(kTimeStep);
  vessel_ = CybershipModel::Step(vessel_, tau, kTimeStep);
  ++steps_;
  Sense();
}

void World::Sense() {
  const Eigen::Vector2d position = vessel_.head<2>();
  navigation_ = Navigate(*path_, position, vessel_[2]);
  if (obstacle_list_refresh_ == 0) {
    range_finder_.Scan(position, vessel_[2], static_obstacles_, hulls_, ranges_.data());
  } else {
    if (steps_ % obstacle_list_refresh_ == 0) ListNearbyObstacles();
    range_finder_.Scan(position, vessel_[2], listed_circles_, listed_hulls_, ranges_.data());
  }
  collision_ = collision_checker_.Collides(position, moving_obstacles_);
}

void World::ListNearbyObstacles() {
  const Eigen::Vector2d position = vessel_.head<2>();
  listed_circles_.clear();
  for (const CircleSpec& circle : static_obstacles_) {
    if (DistanceToCircleBoundary(position, circle) < kListingDistance) {
      listed_circles_.push_back(circle);
    }
  }
  listed_hulls_.clear();
  for (const ConvexPolygon* hull : hulls_) {
    if (DistanceToPolygon(position, *hull) < kListingDistance) listed_hulls_.push_back(hull);
  }
}

}  // namespace colav

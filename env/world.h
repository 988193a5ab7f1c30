// The simulated world of one episode: path, vessel, obstacles, and what the vessel senses.
//
// Step order (reference-simulator 7.1): obstacles advance, then the vessel is integrated, then
// navigation and sensing.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "env/collision_checker.h"
#include "env/navigation.h"
#include "env/obstacles.h"
#include "env/path.h"
#include "env/range_finder.h"
#include "env/scenario.h"
#include "env/vessel_model.h"

namespace colav {

/// Simulation step (s).
inline constexpr double kTimeStep = 1.0;

class World {
 public:
  /// `obstacle_list_refresh`: EnvironmentConfig::obstacle_list_refresh (0: sense every obstacle).
  explicit World(int obstacle_list_refresh = 0);
  // Holds views into its own obstacle list: not copyable.
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Sets up the scenario's initial world and senses it (the reset observation).
  void Load(const Scenario& scenario);

  /// Advances one time step under the force tau.
  void Advance(const GeneralisedForce& tau);

  const Path& path() const { return *path_; }
  const VesselState& vessel() const { return vessel_; }
  const NavigationState& navigation() const { return navigation_; }
  const std::array<double, kNumRays>& ranges() const { return ranges_; }
  bool collision() const { return collision_; }
  const std::vector<CircleSpec>& static_obstacles() const { return static_obstacles_; }
  const std::vector<MovingObstacle>& moving_obstacles() const { return moving_obstacles_; }

 private:
  void Sense();
  /// Rebuilds the nearby-obstacle list from the vessel's position (reference-simulator 6.2).
  void ListNearbyObstacles();

  std::optional<Path> path_;
  VesselState vessel_ = VesselState::Zero();
  std::vector<CircleSpec> static_obstacles_;
  std::vector<MovingObstacle> moving_obstacles_;
  std::vector<const ConvexPolygon*> hulls_;  ///< views of moving_obstacles_' hulls
  int obstacle_list_refresh_;
  std::int64_t steps_ = 0;  ///< since Load
  /// With an obstacle list: the obstacles listed at its last rebuild (hulls keep moving).
  std::vector<CircleSpec> listed_circles_;
  std::vector<const ConvexPolygon*> listed_hulls_;
  RangeFinder range_finder_;
  CollisionChecker collision_checker_;
  NavigationState navigation_;
  std::array<double, kNumRays> ranges_{};
  bool collision_ = false;
};

}  // namespace colav

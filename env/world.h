// The simulated world of one episode: path, vessel, obstacles, and what the vessel senses.
//
// Step order (reference-simulator 7.1): obstacles advance, then the vessel is integrated, then
// navigation and sensing.
#pragma once

#include <array>
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
  World();
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

  std::optional<Path> path_;
  VesselState vessel_ = VesselState::Zero();
  std::vector<CircleSpec> static_obstacles_;
  std::vector<MovingObstacle> moving_obstacles_;
  std::vector<const ConvexPolygon*> hulls_;  ///< views of moving_obstacles_' hulls
  RangeFinder range_finder_;
  CollisionChecker collision_checker_;
  NavigationState navigation_;
  std::array<double, kNumRays> ranges_{};
  bool collision_ = false;
};

}  // namespace colav

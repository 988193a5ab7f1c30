// Collision test of the vessel disc (radius 1.255 m) against every obstacle shape, with FCL.
//
// FCL is 3-D: the vessel is a sphere and the obstacles vertical prisms (cylinders, pentagonal
// prisms) through the plane z = 0, so sphere and prism overlap exactly when the disc and the
// obstacle's outline overlap in the plane. A bounding-circle test first skips every obstacle
// that cannot touch the disc; FCL decides the rest (measured faster than FCL's broad-phase
// managers for 28 obstacles that all move every step).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "env/obstacles.h"

namespace colav {

class CollisionChecker {
 public:
  explicit CollisionChecker(double vessel_radius);
  ~CollisionChecker();
  CollisionChecker(CollisionChecker&&) noexcept;
  CollisionChecker& operator=(CollisionChecker&&) noexcept;

  /// Builds the FCL shapes of a scenario's obstacles (moving hulls in their local frame).
  void Load(const std::vector<CircleSpec>& circles, const std::vector<MovingObstacle>& vessels);

  /// Whether the vessel disc at `position` overlaps any obstacle (moving ones where they are
  /// now).
  bool Collides(const Eigen::Vector2d& position, const std::vector<MovingObstacle>& vessels);

 private:
  struct Shapes;
  double vessel_radius_;
  std::vector<CircleSpec> circles_;
  std::unique_ptr<Shapes> shapes_;
};

}  // namespace colav

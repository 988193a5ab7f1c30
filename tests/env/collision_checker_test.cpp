// FCL collision against the analytic disc distance.
#include "env/collision_checker.h"

#include <gtest/gtest.h>

#include <cmath>

#include "src/random.h"

namespace colav {
namespace {

constexpr double kRadius = 1.255;

// Exact distance from a point to a convex polygon's outline (0 inside).
double PolygonDistance(const ConvexPolygon& hull, const Eigen::Vector2d& p) {
  bool inside = true;
  double best = 1e300;
  for (int k = 0; k < hull.size; ++k) {
    const Eigen::Vector2d a = hull.vertices[k];
    const Eigen::Vector2d b = hull.vertices[(k + 1) % hull.size];
    inside &= hull.normals[k].dot(p - a) <= 0.0;
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - p).norm());
  }
  return inside ? 0.0 : best;
}

TEST(CollisionChecker, CircleMatchesAnalyticDistance) {
  CollisionChecker checker(kRadius);
  checker.Load({{{10.0, 0.0}, 5.0}}, {});
  EXPECT_TRUE(checker.Collides({3.8, 0.0}, {}));   // clearance 6.2 - 6.255 < 0
  EXPECT_FALSE(checker.Collides({3.7, 0.0}, {}));  // clearance 6.3 - 6.255 > 0
  EXPECT_TRUE(checker.Collides({10.0, 0.0}, {}));  // centre
  Rng rng(3);
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector2d p(Uniform(rng, 0, 20), Uniform(rng, -10, 10));
    const double clearance = (p - Eigen::Vector2d(10, 0)).norm() - 5.0 - kRadius;
    if (std::fabs(clearance) < 1e-6) continue;  // the boundary itself is tolerance-limited
    ASSERT_EQ(checker.Collides(p, {}), clearance < 0.0) << p.transpose();
  }
}

TEST(CollisionChecker, MovingHullMatchesAnalyticDistance) {
  VesselObstacleSpec spec;
  spec.position = {0.0, 0.0};
  spec.width = 8.0;
  spec.course = 0.6;
  spec.speed = 0.5;
  std::vector<MovingObstacle> vessels = {MovingObstacle(spec)};
  CollisionChecker checker(kRadius);
  checker.Load({}, vessels);
  Rng rng(5);
  for (int step = 0; step < 3; ++step) {
    for (int k = 0; k < 1500; ++k) {
      const Eigen::Vector2d p =
          vessels[0].position() + Eigen::Vector2d(Uniform(rng, -16, 16), Uniform(rng, -16, 16));
      const double clearance = PolygonDistance(vessels[0].hull(), p) - kRadius;
      if (std::fabs(clearance) < 1e-4) continue;
      ASSERT_EQ(checker.Collides(p, vessels), clearance < 0.0)
          << "step " << step << " point " << p.transpose() << " clearance " << clearance;
    }
    vessels[0].Advance(10.0);  // the checker follows the obstacle
  }
}

}  // namespace
}  // namespace colav

// PCHIP, path smoothing, projection and guidance errors.
#include "env/path.h"

#include <gtest/gtest.h>

#include "env/angles.h"
#include "env/navigation.h"
#include "env/pchip.h"
#include "src/random.h"

namespace colav {
namespace {

TEST(Pchip, SlopesByHand) {
  // x = 0, 1, 3; y = 0, 2, 3: m = (2, 0.5); interior: w1 = 2*2+1 = 5, w2 = 2+2*1 = 4,
  // d1 = (5+4)/(5/2+4/0.5) = 9/10.5; ends: d0 = ((2*1+2)*2 - 1*0.5)/3 = 7.5/3 = 2.5 (same sign
  // as m0, m0 and m1 same sign: kept); d2 = ((2*2+1)*0.5 - 2*2)/3 = -1.5/3 -> sign differs: 0.
  const std::vector<double> d = PchipSlopes({0.0, 1.0, 3.0}, {0.0, 2.0, 3.0});
  EXPECT_DOUBLE_EQ(d[0], 2.5);
  EXPECT_DOUBLE_EQ(d[1], 9.0 / 10.5);
  EXPECT_DOUBLE_EQ(d[2], 0.0);
}

TEST(Pchip, ExtremumGetsZeroSlopeAndEdgeLimit) {
  // m = (1, -1): interior slope 0; end: d0 = ((2+1)*1 - 1*(-1))/2 = 2, signs of m differ and
  // |2| <= 3: kept.
  const std::vector<double> d = PchipSlopes({0.0, 1.0, 2.0}, {0.0, 1.0, 0.0});
  EXPECT_DOUBLE_EQ(d[1], 0.0);
  EXPECT_DOUBLE_EQ(d[0], 2.0);
  EXPECT_DOUBLE_EQ(d[2], -2.0);
}

TEST(Pchip, InterpolatesKnotsAndHermiteMidpoint) {
  const PchipCurve curve({0.0, 1.0, 3.0}, {{0.0, 0.0}, {2.0, 1.0}, {3.0, 5.0}});
  EXPECT_NEAR((curve.Evaluate(1.0) - Eigen::Vector2d(2.0, 1.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((curve.Evaluate(3.0) - Eigen::Vector2d(3.0, 5.0)).norm(), 0.0, 1e-15);
  // Hermite midpoint on [0, 1] for x: (y0+y1)/2 + h (d0-d1)/8 = 1 + (2.5 - 9/10.5)/8.
  EXPECT_NEAR(curve.Evaluate(0.5).x(), 1.0 + (2.5 - 9.0 / 10.5) / 8.0, 1e-14);
}

TEST(Path, StraightPathIsArclengthParametrised) {
  const Path path({{0.0, 0.0}, {100.0, 0.0}});
  EXPECT_NEAR(path.length(), 100.0, 1e-9);
  EXPECT_NEAR(path.Point(37.5).x(), 37.5, 1e-9);
  EXPECT_NEAR(path.Direction(50.0), 0.0, 1e-12);
}

TEST(Navigation, WorkedExample) {
  // reference-simulator 4.3: straight path (0,0)->(100,0), vessel at (10,5), psi 0.3.
  const Path path({{0.0, 0.0}, {100.0, 0.0}});
  const NavigationState nav = Navigate(path, {10.0, 5.0}, 0.3);
  EXPECT_NEAR(nav.closest_arclength, 10.0, 1e-9);
  EXPECT_NEAR(nav.cross_track_error, -5.0, 1e-9);
  EXPECT_NEAR(nav.heading_error, -0.3554985, 1e-7);
  EXPECT_NEAR(nav.look_ahead_heading_error, -0.3, 1e-12);
  EXPECT_NEAR(nav.progress, 0.1, 1e-9);
}

TEST(PolylineProjector, FastSearchEqualsBruteForce) {
  Rng rng(7);
  std::vector<Eigen::Vector2d> waypoints = {{150, 0}, {60, 40}, {0, 0}, {-70, -60}, {-150, 0}};
  const Path path(waypoints);
  for (int k = 0; k < 20000; ++k) {
    const Eigen::Vector2d p(Uniform(rng, -300, 300), Uniform(rng, -300, 300));
    ASSERT_EQ(path.projector().Project(p), path.projector().ProjectBruteForce(p)) << p.transpose();
  }
  // Vertices themselves and points on segments (exact ties between neighbours).
  for (const Eigen::Vector2d& v : path.projector().vertices()) {
    ASSERT_EQ(path.projector().Project(v), path.projector().ProjectBruteForce(v));
  }
}

TEST(Angles, WrapToHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(WrapAngle(kPi), -kPi);
  EXPECT_DOUBLE_EQ(WrapAngle(-kPi), -kPi);
  EXPECT_NEAR(WrapAngle(3.0 * kPi / 2.0), -kPi / 2.0, 1e-15);
  EXPECT_NEAR(WrapAngle(0.25), 0.25, 1e-15);
}

}  // namespace
}  // namespace colav

namespace colav {
namespace {

TEST(PolylineProjector, CollinearPathWithRoundingTies) {
  // On a straight path box bounds equal segment distances up to rounding: no block may be
  // pruned by that rounding.
  const Path path({{0.0, 0.0}, {100.0, 0.0}});
  for (double x = -5.0; x <= 105.0; x += 0.37) {
    for (const double y : {-20.0, -5.0, 0.0, 3.0, 5.0}) {
      ASSERT_EQ(path.ClosestArclength({x, y}), path.projector().ProjectBruteForce({x, y}));
    }
  }
}

}  // namespace
}  // namespace colav

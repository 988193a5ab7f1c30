// Ray intersections and the range-finder against analytic geometry.
#include "env/range_finder.h"

#include <gtest/gtest.h>

#include <cmath>

#include "env/angles.h"
#include "env/ray_geometry.h"

namespace colav {
namespace {

const Eigen::Vector2d kOrigin(0.0, 0.0);
const Eigen::Vector2d kEast(1.0, 0.0);

TEST(RayCircle, HitInsideTangentBehindOutOfRange) {
  EXPECT_DOUBLE_EQ(RayCircleDistance(kOrigin, kEast, {50, 0}, 10, 150), 40.0);
  EXPECT_DOUBLE_EQ(RayCircleDistance(kOrigin, kEast, {5, 0}, 10, 150), 0.0);          // inside
  EXPECT_DOUBLE_EQ(RayCircleDistance(kOrigin, kEast, {50, 10}, 10, 150), 50.0);       // tangent
  EXPECT_DOUBLE_EQ(RayCircleDistance(kOrigin, kEast, {-50, 0}, 10, 150), 150.0);      // behind
  EXPECT_DOUBLE_EQ(RayCircleDistance(kOrigin, kEast, {170, 0}, 10, 150), 150.0);      // too far
  EXPECT_DOUBLE_EQ(RayCircleDistance(kOrigin, kEast, {50, 10.001}, 10, 150), 150.0);  // miss
  // Off-axis chord: x = 30 - sqrt(100 - 36) = 22.
  EXPECT_NEAR(RayCircleDistance(kOrigin, kEast, {30, 6}, 10, 150), 22.0, 1e-12);
}

TEST(RayPolygon, EdgesVerticesInsideAndRange) {
  // Hull of width 10 at (50, 0) heading 0: x from 45 to 65 (bow vertex at (65, 0)).
  const ConvexPolygon hull = VesselHull({50, 0}, 10, 0.0);
  EXPECT_NEAR(RayPolygonDistance(kOrigin, kEast, hull, 150), 45.0, 1e-12);  // stern edge
  // From the far side the bow vertex is hit first.
  EXPECT_NEAR(RayPolygonDistance({100, 0}, {-1, 0}, hull, 150), 35.0, 1e-12);
  EXPECT_DOUBLE_EQ(RayPolygonDistance({50, 0}, kEast, hull, 150), 0.0);      // inside
  EXPECT_DOUBLE_EQ(RayPolygonDistance(kOrigin, {-1, 0}, hull, 150), 150.0);  // behind
  EXPECT_DOUBLE_EQ(RayPolygonDistance({-200, 0}, kEast, hull, 150), 150.0);  // out of range
  // Grazing the starboard side y = -5 exactly: touches along the edge from x = 45.
  EXPECT_NEAR(RayPolygonDistance({0, -5}, kEast, hull, 150), 45.0, 1e-12);
  // Bow edge from (55,5) to (65,0): at y = 2.5 it is x = 60.
  EXPECT_NEAR(RayPolygonDistance({100, 2.5}, {-1, 0}, hull, 150), 40.0, 1e-12);
}

TEST(RangeFinder, RayAnglesMatchReference) {
  // Ray 89 straight ahead: circle r = 10 centred 50 m ahead reads 40 m on ray 89 only from
  // a vessel heading north.
  const RangeFinder finder;
  std::array<double, kNumRays> ranges{};
  finder.Scan(kOrigin, kPi / 2.0, {{{0.0, 50.0}, 10.0}}, {}, ranges.data());
  EXPECT_NEAR(ranges[89], 40.0, 1e-9);
  EXPECT_NEAR(ranges[88], ranges[90], 1e-9);
  EXPECT_NEAR(ranges[179], 150.0, 0.0);  // astern
  // Ray 0 is at -178 deg: a circle there.
  const double angle = kPi / 2.0 - kPi + 2.0 * kPi / 180.0;
  finder.Scan(kOrigin, kPi / 2.0, {{{60.0 * std::cos(angle), 60.0 * std::sin(angle)}, 5.0}}, {},
              ranges.data());
  EXPECT_NEAR(ranges[0], 55.0, 1e-9);
}

TEST(RangeFinder, CullingGivesTheSameAsTestingEveryRay) {
  const RangeFinder finder;
  const std::vector<CircleSpec> circles = {
      {{30, 40}, 12}, {{-100, 20}, 30}, {{0, -149}, 5}, {{2, 1}, 1}};
  const ConvexPolygon hull = VesselHull({-20, -60}, 14, 1.0);
  const ConvexPolygon hull2 = VesselHull({140, 10}, 20, -2.0);
  std::array<double, kNumRays> ranges{};
  const double heading = 0.7;
  finder.Scan({0, 0}, heading, circles, {&hull, &hull2}, ranges.data());
  for (int i = 0; i < kNumRays; ++i) {
    const double angle = heading - kPi + (i + 1) * 2.0 * kPi / 180.0;
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    double expected = 150.0;
    for (const CircleSpec& c : circles) {
      expected = std::min(expected, RayCircleDistance({0, 0}, direction, c.center, c.radius, 150));
    }
    for (const ConvexPolygon* h : {&hull, &hull2}) {
      expected = std::min(expected, RayPolygonDistance({0, 0}, direction, *h, 150));
    }
    EXPECT_NEAR(ranges[i], expected, 1e-9) << "ray " << i;
  }
}

TEST(Closeness, LinearAndLog) {
  EXPECT_DOUBLE_EQ(Closeness(150.0, ClosenessTransform::kLinear), 0.0);
  EXPECT_DOUBLE_EQ(Closeness(0.0, ClosenessTransform::kLinear), 1.0);
  EXPECT_DOUBLE_EQ(Closeness(75.0, ClosenessTransform::kLinear), 0.5);
  EXPECT_NEAR(Closeness(150.0, ClosenessTransform::kLog), 0.0, 1e-15);
  EXPECT_NEAR(Closeness(10.0, ClosenessTransform::kLog), 1.0 - std::log(11.0) / std::log(151.0),
              1e-15);
}

}  // namespace
}  // namespace colav

#include "train/dataset/synthetic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "env/angles.h"
#include "src/error.h"
#include "src/random.h"
#include "train/dataset/shape_overlap.h"

namespace colav {
namespace {

TEST(SyntheticScanTest, OneCircleMatchesAnalyticRanges) {
  SyntheticScene scene;
  const Eigen::Vector2d centre(40.0, 30.0);
  const double radius = 12.0;
  scene.circles.push_back({centre, radius});
  const auto ranges = ScanSyntheticScene(scene);
  int hits = 0;
  for (int i = 0; i < kNumRays; ++i) {
    // Ray i points at 2 pi i / 180 - pi / 2 from +x (reference radar.py).
    const double angle = 2.0 * kPi * i / kNumRays - kPi / 2.0;
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    const double along = centre.dot(direction);
    const double miss_squared = centre.squaredNorm() - along * along;
    double expected = 150.0;
    if (along > 0.0 && miss_squared <= radius * radius) {
      expected = along - std::sqrt(radius * radius - miss_squared);
      ++hits;
    }
    EXPECT_NEAR(ranges[i], expected, 1e-4) << "ray " << i;
  }
  // The circle subtends 2 asin(12/50) = 27.8 degrees: 13 or 14 rays.
  EXPECT_GE(hits, 13);
  EXPECT_LE(hits, 14);
}

TEST(SyntheticScanTest, RayOrientationFollowsTheReference) {
  // A circle on -y is seen by ray 0 (angle -pi/2), one on +x by ray 45.
  SyntheticScene below;
  below.circles.push_back({Eigen::Vector2d(0.0, -50.0), 5.0});
  EXPECT_NEAR(ScanSyntheticScene(below)[0], 45.0, 1e-4);
  SyntheticScene right;
  right.circles.push_back({Eigen::Vector2d(80.0, 0.0), 5.0});
  EXPECT_NEAR(ScanSyntheticScene(right)[45], 75.0, 1e-4);
}

TEST(ShapeOverlapTest, KnownCases) {
  const CircleSpec unit{Eigen::Vector2d(0, 0), 1.0};
  EXPECT_TRUE(CirclesOverlap(unit, {Eigen::Vector2d(1.9, 0), 1.0}));
  EXPECT_FALSE(CirclesOverlap(unit, {Eigen::Vector2d(2.1, 0), 1.0}));

  // Square-ish hull of width 10 at the origin, bow along +x to (15, 0).
  const ConvexPolygon hull = VesselHull(Eigen::Vector2d(0, 0), 10.0, 0.0);
  EXPECT_TRUE(CirclePolygonOverlap({Eigen::Vector2d(0, 0), 1.0}, hull));    // centre inside
  EXPECT_TRUE(CirclePolygonOverlap({Eigen::Vector2d(0, 7.0), 2.5}, hull));  // crosses top edge
  EXPECT_FALSE(CirclePolygonOverlap({Eigen::Vector2d(0, 7.0), 1.5}, hull));
  EXPECT_TRUE(CirclePolygonOverlap({Eigen::Vector2d(17.0, 0), 2.5}, hull));  // at the bow
  EXPECT_FALSE(CirclePolygonOverlap({Eigen::Vector2d(17.0, 0), 1.5}, hull));
  // Near the bow's slanted edge: the corner region is outside the hull.
  EXPECT_FALSE(CirclePolygonOverlap({Eigen::Vector2d(12.0, 5.0), 1.0}, hull));

  EXPECT_TRUE(PolygonsOverlap(hull, VesselHull(Eigen::Vector2d(18.0, 0), 10.0, kPi)));
  EXPECT_FALSE(PolygonsOverlap(hull, VesselHull(Eigen::Vector2d(0, 11.0), 10.0, 0.0)));
  // Bounding boxes overlap but a slanted edge separates them.
  EXPECT_FALSE(PolygonsOverlap(hull, VesselHull(Eigen::Vector2d(12.0, 4.0), 2.0, 0.0)));
}

TEST(SyntheticScanTest, ScenesRespectCountsSafeZoneAndSeparation) {
  const SyntheticSceneOptions options;
  const CircleSpec safe_zone{Eigen::Vector2d::Zero(), options.safe_zone_radius};
  for (const ScanGroup group : kSyntheticGroups) {
    for (std::uint64_t k = 0; k < 50; ++k) {
      Rng rng = MakeRng(7, "test", k);
      const SyntheticObstacleCounts counts = ObstacleCountsOf(group);
      const SyntheticScene scene = SampleSyntheticScene(rng, counts, options);
      ASSERT_EQ(static_cast<int>(scene.circles.size()), counts.circles);
      ASSERT_EQ(static_cast<int>(scene.vessels.size()), counts.vessels);
      for (std::size_t a = 0; a < scene.circles.size(); ++a) {
        EXPECT_FALSE(CirclesOverlap(scene.circles[a], safe_zone));
        for (std::size_t b = a + 1; b < scene.circles.size(); ++b) {
          EXPECT_FALSE(CirclesOverlap(scene.circles[a], scene.circles[b]));
        }
        for (const ConvexPolygon& vessel : scene.vessels) {
          EXPECT_FALSE(CirclePolygonOverlap(scene.circles[a], vessel));
        }
      }
      for (std::size_t a = 0; a < scene.vessels.size(); ++a) {
        EXPECT_FALSE(CirclePolygonOverlap(safe_zone, scene.vessels[a]));
        for (std::size_t b = a + 1; b < scene.vessels.size(); ++b) {
          EXPECT_FALSE(PolygonsOverlap(scene.vessels[a], scene.vessels[b]));
        }
      }
      for (const float range : ScanSyntheticScene(scene)) {
        EXPECT_GT(range, options.safe_zone_radius);
        EXPECT_LE(range, 150.0F);
      }
    }
  }
}

// Settings that leave no room for a shape give up with the settings named instead of looping
// forever (a safe zone covering the whole area, circles larger than it).
TEST(SyntheticScanTest, NoRoomForAShapeIsAUserErrorNotAHang) {
  SyntheticSceneOptions covered;
  covered.safe_zone_radius = 140.0;
  covered.extent = 10.0;
  Rng rng = MakeRng(1, "test");
  try {
    SampleSyntheticScene(rng, {3, 2}, covered);
    FAIL() << "expected a UserError";
  } catch (const UserError& error) {
    EXPECT_NE(std::string(error.what()).find("no room for circle 1 of 3"), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("synthetic.safe_zone_radius 140"), std::string::npos);
  }
  SyntheticSceneOptions huge_vessels;
  huge_vessels.width_mean = 100.0;
  huge_vessels.extent = 10.0;
  EXPECT_THROW(RequirePlaceableShapes(huge_vessels), UserError);
  EXPECT_NO_THROW(RequirePlaceableShapes(SyntheticSceneOptions()));
}

}  // namespace
}  // namespace colav

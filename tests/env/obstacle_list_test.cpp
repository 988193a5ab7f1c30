// The reference's nearby-obstacle list (env.obstacle_list_refresh, reference-simulator 6.2): the
// distances it lists obstacles by, and a vessel that comes into range between two rebuilds.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "env/environment.h"
#include "env/obstacles.h"
#include "env/scenario_file.h"

namespace colav {
namespace {

// The square [0, 2] x [0, 2], counter-clockwise, with outward normals.
ConvexPolygon Square() {
  ConvexPolygon square;
  square.size = 4;
  square.vertices = {Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 0), Eigen::Vector2d(2, 2),
                     Eigen::Vector2d(0, 2), Eigen::Vector2d::Zero()};
  square.normals = {Eigen::Vector2d(0, -1), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1),
                    Eigen::Vector2d(-1, 0), Eigen::Vector2d::Zero()};
  return square;
}

TEST(ObstacleDistance, PolygonInsideBesideAnEdgeAndBeyondAVertex) {
  const ConvexPolygon square = Square();
  EXPECT_DOUBLE_EQ(DistanceToPolygon({1.0, 1.5}, square), 0.0);
  EXPECT_DOUBLE_EQ(DistanceToPolygon({1.0, 5.0}, square), 3.0);   // above the top edge
  EXPECT_DOUBLE_EQ(DistanceToPolygon({-0.5, 1.0}, square), 0.5);  // left of the left edge
  EXPECT_DOUBLE_EQ(DistanceToPolygon({5.0, 6.0}, square), 5.0);   // (3, 4) from the corner (2, 2)
}

TEST(ObstacleDistance, CircleBoundaryFromOutsideAndInside) {
  const CircleSpec circle{{10.0, 0.0}, 4.0};
  EXPECT_DOUBLE_EQ(DistanceToCircleBoundary({0.0, 0.0}, circle), 6.0);
  EXPECT_DOUBLE_EQ(DistanceToCircleBoundary({11.0, 0.0}, circle), 3.0);
}

constexpr double kZeroForce[kActionSize] = {-1.0, 0.0};  // no thrust, no moment: the vessel waits
constexpr int kAheadRay = 89;
constexpr double kVesselWidth = 10.0;  // hull from 5 m behind its position to 15 m ahead

// Our vessel waits at the origin facing +x; a vessel heads straight at it at `speed` m/s, its bow
// `bow_distance` m away at the reset.
Environment Approach(int obstacle_list_refresh, double bow_distance, double speed) {
  Scenario scenario;
  scenario.name = "approach";
  scenario.waypoints = {{0.0, 0.0}, {500.0, 0.0}};
  VesselObstacleSpec vessel;
  vessel.position = {bow_distance + 1.5 * kVesselWidth, 0.0};
  vessel.width = kVesselWidth;
  vessel.course = std::acos(-1.0);
  vessel.speed = speed;
  scenario.dynamic_obstacles = {vessel};
  EnvironmentConfig config;
  config.obstacle_list_refresh = obstacle_list_refresh;
  return Environment(config, std::make_shared<FixedScenarioSource>(scenario));
}

TEST(ObstacleList, AVesselComingIntoRangeStaysUnseenUntilTheNextRebuild) {
  // The bow is 155 m away at the reset (not listed: 155 > 150 + our 1.255 m) and 1 m/s closer
  // every step: in range from step 6, listed at the rebuild of step 25.
  Environment every_step = Approach(0, 155.0, 1.0);
  Environment listed = Approach(25, 155.0, 1.0);
  std::vector<float> observation(kObservationSize);
  every_step.Reset(0, observation.data());
  listed.Reset(0, observation.data());
  for (int step = 1; step <= 30; ++step) {
    every_step.Step(kZeroForce, observation.data());
    listed.Step(kZeroForce, observation.data());
    const std::array<double, kNumRays>& seen = listed.world().ranges();
    if (step < 25) {
      for (double range : seen) ASSERT_EQ(range, RangeFinder::kRange) << "step " << step;
    } else {
      EXPECT_EQ(seen, every_step.world().ranges()) << "step " << step;
      EXPECT_NEAR(seen[kAheadRay], 155.0 - step, 1e-9) << "step " << step;
    }
  }
  EXPECT_NEAR(every_step.world().ranges()[kAheadRay], 125.0, 1e-9);
}

TEST(ObstacleList, AnObstacleListedAtTheResetIsSeenAsItMoves) {
  // 151 m: out of the range-finder's reach but listed (151 < 151.255), so seen from step 2 on.
  Environment listed = Approach(25, 151.0, 1.0);
  std::vector<float> observation(kObservationSize);
  listed.Reset(0, observation.data());
  for (int step = 1; step <= 3; ++step) listed.Step(kZeroForce, observation.data());
  EXPECT_NEAR(listed.world().ranges()[kAheadRay], 148.0, 1e-9);
}

TEST(ObstacleList, CollisionsCountWithObstaclesNotListed) {
  // 10 m/s from 160 m: the hull reaches our vessel before the first rebuild, unseen.
  Environment listed = Approach(2000, 160.0, 10.0);
  std::vector<float> observation(kObservationSize);
  listed.Reset(0, observation.data());
  StepResult result;
  int step = 0;
  while (!result.terminated && step < 20) {
    result = listed.Step(kZeroForce, observation.data());
    ++step;
  }
  EXPECT_TRUE(result.collision);
  EXPECT_EQ(step, 16);  // the bow at 160 - 10 * 16 = 0 m, inside our 1.255 m disc
  for (double range : listed.world().ranges()) EXPECT_EQ(range, RangeFinder::kRange);
}

}  // namespace
}  // namespace colav

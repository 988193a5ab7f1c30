// A collision replayed from its actions: a vessel closing head-on at 2 m/s on ours, at rest,
// comes within 150 m about 74 s before the contact, dead ahead; from then on there is time to
// get out of its way, 10 s before the contact there is not.
#include "eval/collision_analysis.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/eval/head_on_encounter.h"

namespace colav {
namespace {

using ::testing::HasSubstr;

Scenario HeadOn() {
  Scenario scenario = testing_util::HeadOnEncounter(300.0, 2.0);
  scenario.static_obstacles = {CircleSpec{Eigen::Vector2d(0.0, -300.0), 10.0}};
  return scenario;
}

// Thrust 0 N, no moment: the vessel stays at rest.
std::vector<std::array<float, kActionSize>> Drifting(int steps) {
  return std::vector<std::array<float, kActionSize>>(steps, {-1.0F, 0.0F});
}

TEST(CollisionAnalysisTest, AHeadOnVesselIsNamedWithItsWarningTimeAndAvoidability) {
  const std::optional<CollisionAnalysis> analysis = AnalyseCollision(HeadOn(), Drifting(400));
  ASSERT_TRUE(analysis.has_value());
  EXPECT_TRUE(analysis->moving_obstacle);
  EXPECT_EQ(analysis->obstacle, 0);
  EXPECT_DOUBLE_EQ(analysis->obstacle_speed, 2.0);
  EXPECT_NEAR(analysis->bearing_deg, 0.0, 1.0);
  // The gap closes at 2 m/s from 150 m to the vessel's radius 1.255 m.
  EXPECT_NEAR(analysis->contact_step - analysis->detection_step, (150.0 - 1.255) / 2.0, 1.0);
  EXPECT_TRUE(analysis->avoidable_from_detection);
  EXPECT_FALSE(analysis->avoidable_before[0]);  // 10 s
  EXPECT_TRUE(analysis->avoidable_before[2]);   // 60 s
}

TEST(CollisionAnalysisTest, ActionsThatDoNotCollideHaveNoAnalysis) {
  EXPECT_FALSE(AnalyseCollision(HeadOn(), Drifting(20)).has_value());
}

TEST(CollisionAnalysisTest, TheTablesCountPerModel) {
  CollisionAnalysis unavoidable;
  unavoidable.moving_obstacle = true;
  CollisionAnalysis avoidable = unavoidable;
  avoidable.avoidable_from_detection = true;
  avoidable.avoidable_before = {false, true, true};
  const std::string table = CollisionSummaryMarkdown({{"agent", 1000, {unavoidable, avoidable}}});
  EXPECT_THAT(table, HasSubstr("| agent | 1000 | 2 (0.2 %) | 2 (0.2 %) | 1 (0.1 %) | 2 (0.2 %) | "
                               "1 (0.1 %) | 1 (0.1 %) |"));
  EXPECT_THAT(CollisionCsvRow("agent", "test-007", avoidable),
              HasSubstr("agent,test-007,0,vessel,0,0.000,0.0,0,0,1,0,1,1"));
}

}  // namespace
}  // namespace colav

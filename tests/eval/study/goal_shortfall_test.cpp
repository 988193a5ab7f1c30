#include "eval/study/goal_shortfall.h"

#include <gtest/gtest.h>

namespace colav {
namespace {

// A model's summary with these means (progress and collisions in %, cte in m).
ModelSummary Means(const std::string& name, double progress, double cte, double collisions) {
  ModelSummary summary;
  summary.name = name;
  summary.metrics["progress"].mean = progress;
  summary.metrics["cross_track_error"].mean = cte;
  summary.metrics["collision"].mean = collisions;
  return summary;
}

// Configurations "wide" and "close", and the pair of both; issue 16's goal.
StudySpec TwoRunsAndTheirPair() {
  StudySpec spec;
  spec.ppo_seeds = 2;
  spec.ppo_configs = {{"wide", "baseline", "", true, {}}, {"close", "baseline", "", true, {}}};
  spec.ensembles = {{"pair", {"wide", "close"}, 2, std::nullopt, std::nullopt}};
  spec.evaluation.goal = {{"progress", 97.0}, {"cross_track_error", 17.0}, {"collision", 3.0}};
  return spec;
}

TEST(GoalShortfallTest, EachMeanFallsShortOfItsBoundInItsOwnDirection) {
  const StudySpec spec = TwoRunsAndTheirPair();
  ScenarioSetReport report;
  report.models = {Means("wide", 98.0, 19.5, 2.0), Means("close", 96.5, 16.0, 3.25),
                   Means("pair", 97.0, 17.0, 3.0), Means("ref.agent", 90.0, 30.0, 9.0)};
  const std::vector<GoalShortfall> shortfalls = MeasureGoalShortfalls(spec, report);
  ASSERT_EQ(shortfalls.size(), 3U);  // the study's models, not the reference agent
  EXPECT_EQ(shortfalls[0].model, "wide");
  EXPECT_EQ(shortfalls[0].networks, 1);
  EXPECT_DOUBLE_EQ(shortfalls[0].by_metric.at("cross_track_error"), 2.5);  // over "at most 17"
  EXPECT_DOUBLE_EQ(shortfalls[0].by_metric.at("progress"), 0.0);           // 1 point to spare
  EXPECT_DOUBLE_EQ(shortfalls[0].total, 2.5);
  // Short of "at least 97" by 0.5 points, over "at most 3" by 0.25: 0.75 in all.
  EXPECT_DOUBLE_EQ(shortfalls[1].by_metric.at("progress"), 0.5);
  EXPECT_DOUBLE_EQ(shortfalls[1].by_metric.at("collision"), 0.25);
  EXPECT_DOUBLE_EQ(shortfalls[1].total, 0.75);
  EXPECT_FALSE(shortfalls[1].met());
  // On every bound exactly: met.
  EXPECT_EQ(shortfalls[2].model, "pair");
  EXPECT_EQ(shortfalls[2].networks, 2);
  EXPECT_DOUBLE_EQ(shortfalls[2].total, 0.0);
  EXPECT_TRUE(shortfalls[2].met());
  EXPECT_EQ(&ChooseByShortfall(shortfalls), &shortfalls[2]);
}

TEST(GoalShortfallTest, TiesGoToFewerNetworksThenToTheFirst) {
  const std::vector<GoalShortfall> shortfalls = {
      {"pair", 2, {}, 0.0}, {"first", 1, {}, 0.0}, {"second", 1, {}, 0.0}, {"close", 1, {}, 0.1}};
  EXPECT_EQ(ChooseByShortfall(shortfalls).model, "first");
  // A smaller shortfall wins over fewer networks.
  const std::vector<GoalShortfall> smaller = {{"single", 1, {}, 0.3}, {"pair", 2, {}, 0.2}};
  EXPECT_EQ(ChooseByShortfall(smaller).model, "pair");
  // Sums of the same means in another order are a tie, not a win: 0.1 + 0.2 exceeds 0.3 by
  // rounding, and the pair's 0.3 does not beat it.
  const std::vector<GoalShortfall> rounding = {{"single", 1, {}, 0.1 + 0.2}, {"pair", 2, {}, 0.3}};
  EXPECT_EQ(ChooseByShortfall(rounding).model, "single");
}

}  // namespace
}  // namespace colav

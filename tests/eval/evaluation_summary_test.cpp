// The statistics of an evaluation: the Student-t intervals of the paper's DRL table, the intervals
// that stay in range, and the paired differences between models.
#include "eval/evaluation_summary.h"

#include <gtest/gtest.h>

namespace colav {
namespace {

// `collisions` of `count` episodes collided; every other metric is constant.
std::vector<EpisodeMetrics> EpisodesWithCollisions(int count, int collisions) {
  std::vector<EpisodeMetrics> episodes(count);
  for (int k = 0; k < collisions; ++k) episodes[k].collision = true;
  return episodes;
}

std::vector<EpisodeMetrics> EpisodesWithProgress(const std::vector<double>& progress) {
  std::vector<EpisodeMetrics> episodes;
  for (const double p : progress) {
    EpisodeMetrics episode;
    episode.progress = p;
    episodes.push_back(episode);
  }
  return episodes;
}

TEST(EvaluationSummary, CollisionRateIntervalsMatchThePaperTable) {
  // The paper's collision column: 4, 5 and 7 collisions in 100 episodes give these t-intervals.
  const struct {
    int collisions;
    double low, high;
  } cases[] = {{4, 0.0009215643, 0.0790784357},
               {5, 0.0065371338, 0.0934628662},
               {7, 0.0191182485, 0.1208817515}};
  for (const auto& c : cases) {
    const ModelSummary summary =
        SummariseModel("m", "m.pt", EpisodesWithCollisions(100, c.collisions));
    const MeanConfidenceInterval& rate = FindMetric(summary.metrics, "collision").interval;
    EXPECT_EQ(summary.collisions, c.collisions);
    EXPECT_NEAR(rate.mean, c.collisions / 100.0, 1e-12);
    EXPECT_NEAR(rate.low, c.low, 1e-8);
    EXPECT_NEAR(rate.high, c.high, 1e-8);
    EXPECT_EQ(rate.count, 100U);
  }
}

TEST(EvaluationSummary, RatesGetWilsonIntervalsThatStayInRange) {
  // 1 collision in 6 episodes: Student-t leaves [0, 1] ("16.7 % [-26.2, 59.5]"), Wilson does not:
  // (p + z^2/2n -+ z sqrt(p(1-p)/n + z^2/4n^2)) / (1 + z^2/n) = [0.0301, 0.5635].
  const ModelSummary one = SummariseModel("m", "m.pt", EpisodesWithCollisions(6, 1));
  const MetricSummary& rate = FindMetric(one.metrics, "collision");
  EXPECT_LT(rate.interval.low, 0.0);
  EXPECT_NEAR(rate.in_range.low, 0.030053, 1e-6);
  EXPECT_NEAR(rate.in_range.high, 0.563503, 1e-6);
  // None of the 6 goals reached: [0, z^2 / (n + z^2)].
  const MetricSummary& goals = FindMetric(one.metrics, "goal");
  EXPECT_EQ(goals.in_range.low, 0.0);
  EXPECT_NEAR(goals.in_range.high, 3.841459 / (6 + 3.841459), 1e-6);
}

TEST(EvaluationSummary, ProgressGetsABootstrapIntervalInsideItsValues) {
  const ModelSummary summary =
      SummariseModel("m", "m.pt", EpisodesWithProgress({1.0, 1.0, 1.0, 0.2, 1.0, 0.9}));
  const MetricSummary& progress = FindMetric(summary.metrics, "progress");
  EXPECT_GT(progress.interval.high, 1.0);  // Student-t leaves the range
  EXPECT_GE(progress.in_range.low, 0.2);
  EXPECT_LE(progress.in_range.high, 1.0);
  EXPECT_LT(progress.in_range.low, progress.interval.mean);
  EXPECT_EQ(SummariseModel("m", "m.pt", EpisodesWithProgress({1.0, 1.0, 1.0, 0.2, 1.0, 0.9}))
                .metrics[0]
                .in_range.low,
            progress.in_range.low);  // a fixed bootstrap seed: the same summary every time
}

TEST(EvaluationSummary, CountsGoalsCollisionsAndTruncations) {
  std::vector<EpisodeMetrics> episodes(4);
  episodes[0].goal_reached = true;
  episodes[1].goal_reached = true;
  episodes[2].collision = true;
  episodes[3].truncated = true;
  episodes[3].steps = 2000;
  const ModelSummary summary = SummariseModel("m", "m.pt", episodes);
  EXPECT_EQ(summary.episodes, 4);
  EXPECT_EQ(summary.goals_reached, 2);
  EXPECT_EQ(summary.collisions, 1);
  EXPECT_EQ(summary.truncated, 1);
  EXPECT_DOUBLE_EQ(FindMetric(summary.metrics, "goal").interval.mean, 0.5);
  EXPECT_DOUBLE_EQ(FindMetric(summary.metrics, "duration").interval.mean, 500.0);
  ASSERT_EQ(summary.metrics.size(), SummaryMetrics().size());
}

TEST(EvaluationSummary, PairedDifferenceOfAConstructedCase) {
  // Differences 1, 0, 2, 0: mean 0.75, sd 0.957427, t(0.975, 3) = 3.182446.
  const PairedDifference difference =
      CompareModels("a", EpisodesWithProgress({1.0, 2.0, 3.0, 4.0}), "b",
                    EpisodesWithProgress({0.0, 2.0, 1.0, 4.0}));
  EXPECT_EQ(difference.first, "a");
  EXPECT_EQ(difference.second, "b");
  const MeanConfidenceInterval& progress = FindMetric(difference.metrics, "progress").interval;
  EXPECT_DOUBLE_EQ(progress.mean, 0.75);
  EXPECT_NEAR(progress.sd, 0.9574271078, 1e-9);
  EXPECT_NEAR(progress.low, -0.7734801808, 1e-8);
  EXPECT_NEAR(progress.high, 2.2734801808, 1e-8);
}

TEST(EvaluationSummary, PairingRemovesTheScenarioToScenarioSpread) {
  // Model a is exactly 0.05 better on every scenario, whose difficulty varies a lot: the paired
  // interval is the point 0.05, while each model's own interval is wide.
  const std::vector<double> b = {0.2, 0.9, 0.5, 0.7, 0.3};
  std::vector<double> a;
  for (const double value : b) a.push_back(value + 0.05);
  const PairedDifference difference =
      CompareModels("a", EpisodesWithProgress(a), "b", EpisodesWithProgress(b));
  const MeanConfidenceInterval& paired = FindMetric(difference.metrics, "progress").interval;
  EXPECT_NEAR(paired.mean, 0.05, 1e-12);
  EXPECT_NEAR(paired.half_width, 0.0, 1e-12);
  const ModelSummary alone = SummariseModel("a", "a.pt", EpisodesWithProgress(a));
  EXPECT_GT(FindMetric(alone.metrics, "progress").interval.half_width, 0.3);
}

TEST(EvaluationSummary, PairedDifferenceNeedsTheSameEpisodes) {
  EXPECT_THROW(
      CompareModels("a", EpisodesWithProgress({1.0, 2.0}), "b", EpisodesWithProgress({1.0})),
      std::invalid_argument);
}

}  // namespace
}  // namespace colav

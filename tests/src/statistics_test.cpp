#include "src/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace colav {
namespace {

TEST(StatisticsTest, MeanAndSampleStandardDeviation) {
  const std::vector<double> values = {2, 4, 4, 4, 5, 5, 7, 9};
  EXPECT_DOUBLE_EQ(Mean(values), 5.0);
  EXPECT_NEAR(SampleStandardDeviation(values), 2.138089935299395, 1e-12);  // ddof 1
  EXPECT_EQ(SampleStandardDeviation({3.0}), 0.0);
  EXPECT_THROW(Mean({}), std::invalid_argument);
}

TEST(StatisticsTest, StudentTQuantilesMatchTables) {
  EXPECT_NEAR(StudentTQuantile(0.975, 9), 2.262157163, 1e-8);
  EXPECT_NEAR(StudentTQuantile(0.975, 4), 2.776445105, 1e-8);
  EXPECT_NEAR(StudentTQuantile(0.975, 99), 1.984216952, 1e-8);
  EXPECT_NEAR(StudentTQuantile(0.975, 1), 12.70620474, 1e-7);
  EXPECT_NEAR(StudentTQuantile(0.5, 7), 0.0, 1e-12);
  EXPECT_NEAR(StudentTQuantile(0.025, 9), -2.262157163, 1e-8);
  EXPECT_NEAR(StudentTCdf(2.262157163, 9), 0.975, 1e-9);
  EXPECT_NEAR(StudentTCdf(-1.0, 3), 0.19550110947788, 1e-10);
}

TEST(StatisticsTest, ConfidenceIntervalOfTenValues) {
  const std::vector<double> values = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  const MeanConfidenceInterval summary = Summarise(values);
  EXPECT_EQ(summary.count, 10U);
  EXPECT_DOUBLE_EQ(summary.mean, 5.5);
  EXPECT_NEAR(summary.sd, 3.0276503540974917, 1e-12);
  // scipy.stats.t.interval(0.95, 9, loc=5.5, scale=sem) = (3.3341, 7.6659).
  EXPECT_NEAR(summary.half_width, 2.262157163 * 3.0276503540974917 / std::sqrt(10.0), 1e-8);
  EXPECT_NEAR(summary.low, 3.334149, 1e-6);
  EXPECT_NEAR(summary.high, 7.665851, 1e-6);
}

TEST(StatisticsTest, SingleValueHasNoInterval) {
  const MeanConfidenceInterval summary = Summarise({42.0});
  EXPECT_EQ(summary.mean, 42.0);
  EXPECT_EQ(summary.half_width, 0.0);
  EXPECT_EQ(summary.low, 42.0);
  EXPECT_EQ(summary.high, 42.0);
}

// 1..5: mean 3, sd^2 2.5, so sd * sqrt(1 + 1/5) = sqrt(3); the confidence interval's half-width
// is t * sd / sqrt(5), the prediction interval's t * sqrt(3), 2.449 times as wide.
TEST(StatisticsTest, PredictionIntervalForOneMoreValue) {
  const Interval interval = PredictionInterval({1, 2, 3, 4, 5});
  const double half_width = 2.776445105 * std::sqrt(3.0);
  EXPECT_NEAR(interval.low, 3.0 - half_width, 1e-8);
  EXPECT_NEAR(interval.high, 3.0 + half_width, 1e-8);
  const Interval narrower = PredictionInterval({1, 2, 3, 4, 5}, 0.5);
  EXPECT_NEAR(narrower.high - 3.0, StudentTQuantile(0.75, 4) * std::sqrt(3.0), 1e-10);
  EXPECT_THROW(PredictionInterval({42.0}), std::invalid_argument);
}

}  // namespace
}  // namespace colav

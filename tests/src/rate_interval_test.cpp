#include "src/rate_interval.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace colav {
namespace {

TEST(WilsonIntervalTest, KnownValues) {
  // 5 of 10 at 95 %: [0.2366, 0.7634] (e.g. statsmodels proportion_confint(method="wilson")).
  const Interval half = WilsonInterval(5, 10);
  EXPECT_NEAR(half.low, 0.236593, 1e-6);
  EXPECT_NEAR(half.high, 0.763407, 1e-6);
  // 1 of 6 (the quickstart's "16.7 % [-26.2, 59.5]" under Student-t): [0.0301, 0.5635].
  const Interval one_of_six = WilsonInterval(1, 6);
  EXPECT_NEAR(one_of_six.low, 0.030053, 1e-6);
  EXPECT_NEAR(one_of_six.high, 0.563503, 1e-6);
  // 87 of 1000: [0.0711, 0.1061].
  const Interval rate = WilsonInterval(87, 1000);
  EXPECT_NEAR(rate.low, 0.071074, 1e-6);
  EXPECT_NEAR(rate.high, 0.106086, 1e-6);
}

TEST(WilsonIntervalTest, EdgeCountsStayInTheUnitInterval) {
  const double z2 = kNormal95 * kNormal95;
  const Interval none = WilsonInterval(0, 10);
  EXPECT_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, z2 / (10 + z2), 1e-12);
  const Interval all = WilsonInterval(10, 10);
  EXPECT_NEAR(all.low, 10 / (10 + z2), 1e-12);
  EXPECT_EQ(all.high, 1.0);
  const Interval single = WilsonInterval(0, 1);
  EXPECT_GE(single.low, 0.0);
  EXPECT_LE(single.high, 1.0);
  EXPECT_THROW(WilsonInterval(0, 0), std::invalid_argument);
  EXPECT_THROW(WilsonInterval(11, 10), std::invalid_argument);
  EXPECT_THROW(WilsonInterval(-1, 10), std::invalid_argument);
}

TEST(QuantileTest, LinearInterpolationLikeNumpy) {
  const std::vector<double> values = {4, 1, 3, 2};
  EXPECT_DOUBLE_EQ(Quantile(values, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(Quantile(values, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(Quantile(values, 0.5), 2.5);    // numpy.quantile([1,2,3,4], 0.5)
  EXPECT_DOUBLE_EQ(Quantile(values, 0.25), 1.75);  // numpy.quantile([1,2,3,4], 0.25)
  EXPECT_THROW(Quantile({}, 0.5), std::invalid_argument);
  EXPECT_THROW(Quantile(values, 1.5), std::invalid_argument);
}

TEST(PercentileBootstrapTest, StaysInRangeAndIsReproducible) {
  // Progress-like values near the upper bound: Student-t would reach above the largest value.
  std::vector<double> values(20, 1.0);
  values[0] = 0.2;
  const Interval interval = PercentileBootstrapMean(values, 7);
  EXPECT_GE(interval.low, 0.2);
  EXPECT_LE(interval.high, 1.0);
  EXPECT_LT(interval.low, 0.96);  // the mean: 0.96
  EXPECT_DOUBLE_EQ(interval.high, 1.0);
  const Interval again = PercentileBootstrapMean(values, 7);
  EXPECT_EQ(interval.low, again.low);
  EXPECT_EQ(interval.high, again.high);
  const Interval constant = PercentileBootstrapMean(std::vector<double>(5, 0.5), 1);
  EXPECT_EQ(constant.low, 0.5);
  EXPECT_EQ(constant.high, 0.5);
}

TEST(PercentileBootstrapTest, MatchesTheNormalIntervalForManyValues) {
  // 0, 1, 0, 1, ...: mean 0.5, sd 0.5; the 95 % interval of the mean of 2,000 values is about
  // 0.5 +- 1.96 * 0.5 / sqrt(2000) = 0.5 +- 0.0219.
  std::vector<double> values(2000);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<double>(i % 2);
  const Interval interval = PercentileBootstrapMean(values, 3, 4000);
  EXPECT_NEAR(interval.low, 0.4781, 0.003);
  EXPECT_NEAR(interval.high, 0.5219, 0.003);
}

}  // namespace
}  // namespace colav

#include "src/seed_aggregates.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace colav {
namespace {

TEST(InterquartileMeanTest, TrimsAQuarterAtEachEnd) {
  EXPECT_DOUBLE_EQ(InterquartileMean({8, 1, 7, 2, 6, 3, 5, 4}), 4.5);  // mean of 3, 4, 5, 6
  EXPECT_DOUBLE_EQ(InterquartileMean({100, 1, 2, 3, -50}), 2.0);       // n = 5: one cut each end
  EXPECT_DOUBLE_EQ(InterquartileMean({1, 2, 3}), 2.0);                 // n = 3: nothing cut
  EXPECT_DOUBLE_EQ(InterquartileMean({4}), 4.0);
  EXPECT_THROW(InterquartileMean({}), std::invalid_argument);
}

TEST(ProbabilityOfImprovementTest, ConstructedCases) {
  const SeedScores low = {{0, 0, 0}, {0, 0, 0}};
  const SeedScores high = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  EXPECT_DOUBLE_EQ(ProbabilityOfImprovement(high, low), 1.0);
  EXPECT_DOUBLE_EQ(ProbabilityOfImprovement(low, high), 0.0);
  EXPECT_DOUBLE_EQ(ProbabilityOfImprovement(low, low), 0.5);  // ties count half
  // Two seeds of A against one of B on three scenarios.
  const SeedScores a = {{1, 5, 0}, {3, 5, 0}};
  const SeedScores b = {{2, 5, 1}};
  // Scenario 0: (0 + 1) / 2; scenario 1: (0.5 + 0.5) / 2; scenario 2: 0. Mean: (0.5 + 0.5 + 0) / 3.
  EXPECT_DOUBLE_EQ(ProbabilityOfImprovement(a, b), 1.0 / 3.0);
  // Symmetry: P(A > B) + P(B > A) = 1.
  EXPECT_DOUBLE_EQ(ProbabilityOfImprovement(a, b) + ProbabilityOfImprovement(b, a), 1.0);
  EXPECT_THROW(ProbabilityOfImprovement({}, b), std::invalid_argument);
  EXPECT_THROW(ProbabilityOfImprovement({{1, 2}}, {{1}}), std::invalid_argument);
}

TEST(ProbabilityOfImprovementTest, BootstrapIntervalCoversTheEstimateAndSeparatesClearCases) {
  // A beats B on every scenario with every seed: the interval is the single point 1.
  const SeedScores better = {{2, 3, 4, 5}, {2, 3, 4, 5}};
  const SeedScores worse = {{1, 2, 3, 4}, {0, 1, 2, 3}};
  const ImprovementEstimate clear = ProbabilityOfImprovementInterval(better, worse, 1, 500);
  EXPECT_DOUBLE_EQ(clear.probability, 1.0);
  EXPECT_DOUBLE_EQ(clear.ci.low, 1.0);
  // One of two seeds of A is good, the other bad: the seed resampling must show that the answer
  // hangs on which seed was drawn (an interval from clearly below to clearly above 1/2).
  const SeedScores mixed = {{9, 9, 9, 9, 9, 9, 9, 9}, {0, 0, 0, 0, 0, 0, 0, 0}};
  const SeedScores middle = {{5, 5, 5, 5, 5, 5, 5, 5}};
  const ImprovementEstimate split = ProbabilityOfImprovementInterval(mixed, middle, 2, 2000);
  EXPECT_DOUBLE_EQ(split.probability, 0.5);
  EXPECT_LE(split.ci.low, 0.0);
  EXPECT_GE(split.ci.high, 1.0);
  // Reproducible by seed.
  const ImprovementEstimate again = ProbabilityOfImprovementInterval(mixed, middle, 2, 2000);
  EXPECT_EQ(split.ci.low, again.ci.low);
  EXPECT_EQ(split.ci.high, again.ci.high);
  EXPECT_LE(split.ci.low, split.probability);
  EXPECT_GE(split.ci.high, split.probability);
}

}  // namespace
}  // namespace colav

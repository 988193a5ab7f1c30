#include "src/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace colav {
namespace {

constexpr int kDraws = 100000;

struct Moments {
  double mean;
  double variance;
};

Moments SampleMoments(const std::function<double()>& draw) {
  double sum = 0.0;
  double sum_of_squares = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double x = draw();
    sum += x;
    sum_of_squares += x * x;
  }
  const double mean = sum / kDraws;
  return {mean, (sum_of_squares - kDraws * mean * mean) / (kDraws - 1)};
}

// Tolerances are 5 standard errors, so a correct sampler fails with probability < 1e-6 per check
// (and the seeds are fixed anyway), while a biased one is caught.
double MeanTolerance(double variance) { return 5.0 * std::sqrt(variance / kDraws); }

TEST(RandomTest, Uniform01StaysInRangeWithUniformMoments) {
  Rng rng = MakeRng(1, "uniform");
  const Moments m = SampleMoments([&] {
    const double u = Uniform01(rng);
    EXPECT_TRUE(u >= 0.0 && u < 1.0);
    return u;
  });
  EXPECT_NEAR(m.mean, 0.5, MeanTolerance(1.0 / 12));
  EXPECT_NEAR(m.variance, 1.0 / 12, 0.002);
}

TEST(RandomTest, UniformIndexCoversEveryValueEvenly) {
  Rng rng = MakeRng(1, "index");
  std::vector<int> counts(7);
  for (int i = 0; i < kDraws; ++i) ++counts.at(UniformIndex(rng, 7));
  const double p = 1.0 / 7;
  for (const int count : counts) {
    EXPECT_NEAR(count / static_cast<double>(kDraws), p, 5 * std::sqrt(p * (1 - p) / kDraws));
  }
  EXPECT_THROW(UniformIndex(rng, 0), std::invalid_argument);
}

TEST(RandomTest, NormalHasTheRequestedMeanAndVariance) {
  Rng rng = MakeRng(1, "normal");
  const Moments m = SampleMoments([&] { return Normal(rng, 3.0, 2.0); });
  EXPECT_NEAR(m.mean, 3.0, MeanTolerance(4.0));
  // Standard error of the sample variance of a normal: sigma^2 sqrt(2 / n).
  EXPECT_NEAR(m.variance, 4.0, 5 * 4.0 * std::sqrt(2.0 / kDraws));
}

class PoissonTest : public ::testing::TestWithParam<double> {};

// lambda 10 exercises Knuth's method, 30 the PTRS rejection method.
TEST_P(PoissonTest, MeanAndVarianceEqualLambda) {
  const double lambda = GetParam();
  Rng rng = MakeRng(1, "poisson");
  const Moments m = SampleMoments([&] { return static_cast<double>(Poisson(rng, lambda)); });
  EXPECT_NEAR(m.mean, lambda, MeanTolerance(lambda));
  // Standard error of the sample variance: sqrt((mu4 - sigma^4) / n), mu4 = lambda (1 + 3 lambda).
  EXPECT_NEAR(m.variance, lambda, 5 * std::sqrt((lambda + 2 * lambda * lambda) / kDraws));
}

TEST_P(PoissonTest, FrequencyOfTheModeMatchesTheProbabilityMass) {
  const double lambda = GetParam();
  const auto mode = static_cast<std::int64_t>(lambda);
  Rng rng = MakeRng(2, "poisson");
  int hits = 0;
  for (int i = 0; i < kDraws; ++i) hits += Poisson(rng, lambda) == mode ? 1 : 0;
  const double p = std::exp(mode * std::log(lambda) - lambda - std::lgamma(mode + 1.0));
  EXPECT_NEAR(hits / static_cast<double>(kDraws), p, 5 * std::sqrt(p * (1 - p) / kDraws));
}

INSTANTIATE_TEST_SUITE_P(Lambdas, PoissonTest, ::testing::Values(10.0, 30.0));

TEST(RandomTest, PoissonOfZeroIsZero) {
  Rng rng = MakeRng(1, "poisson");
  EXPECT_EQ(Poisson(rng, 0.0), 0);
}

TEST(RandomTest, DiscreteFollowsTheWeights) {
  Rng rng = MakeRng(1, "discrete");
  const std::vector<double> weights = {1.0, 0.0, 2.0, 7.0};
  std::vector<int> counts(weights.size());
  for (int i = 0; i < kDraws; ++i) ++counts.at(Discrete(rng, weights));
  EXPECT_EQ(counts[1], 0);
  for (std::size_t k = 0; k < weights.size(); ++k) {
    const double p = weights[k] / 10.0;
    EXPECT_NEAR(counts[k] / static_cast<double>(kDraws), p,
                5 * std::sqrt(p * (1 - p) / kDraws) + 1e-12);
  }
}

TEST(RandomTest, SameSeedGivesTheSameSamples) {
  Rng a = MakeRng(9, "samples");
  Rng b = MakeRng(9, "samples");
  for (int i = 0; i < 100; ++i) {
    ASSERT_EQ(Normal(a, 0, 1), Normal(b, 0, 1));
    ASSERT_EQ(Poisson(a, 30), Poisson(b, 30));
  }
}

}  // namespace
}  // namespace colav

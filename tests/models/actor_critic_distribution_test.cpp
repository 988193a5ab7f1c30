#include <gtest/gtest.h>

#include <cmath>

#include "tests/models/diagonal_gaussian.h"

namespace colav {
namespace {

TEST(DiagonalGaussianTest, LogProbMatchesTheClosedForm) {
  const DiagonalGaussian gaussian{torch::tensor({{0.5f, -1.0f}}), torch::tensor({0.2f, -0.3f})};
  const double a0 = 1.0, a1 = -2.0;
  double expected = 0.0;
  for (auto [a, mu, log_std] : {std::tuple{a0, 0.5, 0.2}, std::tuple{a1, -1.0, -0.3}}) {
    const double sigma = std::exp(log_std);
    expected += -0.5 * std::pow((a - mu) / sigma, 2) - std::log(sigma) - 0.5 * std::log(2 * M_PI);
  }
  const torch::Tensor log_prob = gaussian.LogProb(torch::tensor({{1.0f, -2.0f}}));
  ASSERT_EQ(log_prob.sizes(), (at::IntArrayRef{1}));
  EXPECT_NEAR(log_prob.item<double>(), expected, 1e-6);
}

TEST(DiagonalGaussianTest, EntropyMatchesTheClosedForm) {
  const DiagonalGaussian gaussian{torch::zeros({3, 2}), torch::tensor({0.2f, -0.3f})};
  // Sum over dimensions of 0.5 * log(2 pi e sigma^2).
  const double expected = 0.5 * std::log(2 * M_PI * M_E * std::exp(0.4)) +
                          0.5 * std::log(2 * M_PI * M_E * std::exp(-0.6));
  const torch::Tensor entropy = gaussian.Entropy();
  ASSERT_EQ(entropy.sizes(), (at::IntArrayRef{3}));
  EXPECT_NEAR(entropy[2].item<double>(), expected, 1e-6);
}

TEST(DiagonalGaussianTest, SamplesAreSeededAndHaveTheRightMoments) {
  const DiagonalGaussian gaussian{torch::full({20000, 2}, 0.25f),
                                  torch::tensor({0.0f, std::log(2.0f)})};
  auto g1 = at::make_generator<at::CPUGeneratorImpl>(5);
  auto g2 = at::make_generator<at::CPUGeneratorImpl>(5);
  const torch::Tensor a = gaussian.Sample(g1);
  EXPECT_TRUE(torch::equal(a, gaussian.Sample(g2)));
  EXPECT_NEAR(a.mean(0)[0].item<double>(), 0.25, 0.03);
  EXPECT_NEAR(a.std(0)[0].item<double>(), 1.0, 0.03);
  EXPECT_NEAR(a.std(0)[1].item<double>(), 2.0, 0.06);
}

}  // namespace
}  // namespace colav

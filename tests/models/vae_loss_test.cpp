#include "models/vae_loss.h"

#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>

namespace colav {
namespace {

// Two samples, two latent dimensions:
//   sample 0: reconstruction 0.5 everywhere (BCE ln 2 per value whatever the target),
//             mu = (1, 0), logvar = (0, ln 2): KL = 1/2 + (1 - ln 2)/2;
//   sample 1: reconstruction 0.9 against target 1 (BCE -ln 0.9 per value), mu = 0, logvar = 0: KL
//   0.
struct TinyCase {
  ConvVaeImpl::Output output;
  torch::Tensor target;
  double bce[2] = {180 * std::log(2.0), -180 * std::log(0.9)};
  double kl[2] = {0.5 + 0.5 * (1 - std::log(2.0)), 0.0};
};

TinyCase MakeTinyCase() {
  TinyCase tiny;
  tiny.output.reconstruction = torch::stack(
      {torch::full({180}, 0.5, torch::kFloat64), torch::full({180}, 0.9, torch::kFloat64)});
  tiny.target = torch::stack(
      {torch::linspace(0, 1, 180, torch::kFloat64), torch::ones({180}, torch::kFloat64)});
  tiny.output.mu = torch::tensor({{1.0, 0.0}, {0.0, 0.0}}, torch::kFloat64);
  tiny.output.logvar = torch::tensor({{0.0, std::log(2.0)}, {0.0, 0.0}}, torch::kFloat64);
  return tiny;
}

TEST(ComputeVaeLoss, AveragesTheSummedTermsOverTheBatch) {
  const TinyCase tiny = MakeTinyCase();
  constexpr double kBeta = 0.5;
  const VaeLoss loss = ComputeVaeLoss(tiny.output, tiny.target, kBeta);
  const double bce = (tiny.bce[0] + tiny.bce[1]) / 2;
  const double kl = (tiny.kl[0] + tiny.kl[1]) / 2;
  EXPECT_NEAR(loss.bce.item<double>(), bce, 1e-10);
  EXPECT_NEAR(loss.kl.item<double>(), kl, 1e-12);
  EXPECT_NEAR(loss.total.item<double>(), bce + kBeta * kl, 1e-10);
  EXPECT_EQ(loss.total.dim(), 0);
}

TEST(ComputePerSampleVaeLoss, GivesEachSamplesTerms) {
  const TinyCase tiny = MakeTinyCase();
  constexpr double kBeta = 2.0;
  const VaeLoss loss = ComputePerSampleVaeLoss(tiny.output, tiny.target, kBeta);
  ASSERT_EQ(loss.total.sizes(), (std::vector<std::int64_t>{2}));
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(loss.bce[i].item<double>(), tiny.bce[i], 1e-10) << "sample " << i;
    EXPECT_NEAR(loss.kl[i].item<double>(), tiny.kl[i], 1e-12) << "sample " << i;
    EXPECT_NEAR(loss.total[i].item<double>(), tiny.bce[i] + kBeta * tiny.kl[i], 1e-10);
  }
  EXPECT_NEAR(loss.total.mean().item<double>(),
              ComputeVaeLoss(tiny.output, tiny.target, kBeta).total.item<double>(), 1e-10);
}

// Noisy targets fall outside [0, 1] and a saturated sigmoid reaches exactly 0 or 1: the loss must
// stay finite, with each log term clamped at -100 as PyTorch does.
TEST(ComputePerSampleVaeLoss, AcceptsNoisyTargetsAndSaturatedReconstructions) {
  ConvVaeImpl::Output output;
  output.reconstruction = torch::full({1, 180}, 0.3, torch::kFloat64);
  output.reconstruction[0][0] = 0.0;
  output.reconstruction[0][1] = 1.0;
  output.reconstruction[0][2] = 0.0;
  torch::Tensor target = torch::full({1, 180}, 0.5, torch::kFloat64);
  target[0][0] = -0.05;
  target[0][1] = 1.05;
  target[0][2] = 1.0;
  output.mu = torch::zeros({1, 2}, torch::kFloat64);
  output.logvar = torch::zeros({1, 2}, torch::kFloat64);

  const double expected = -(-0.05 * -100.0 + 1.05 * 0.0)   // r = 0, t = -0.05
                          - (1.05 * 0.0 + -0.05 * -100.0)  // r = 1, t = 1.05
                          - (1.0 * -100.0)                 // r = 0, t = 1
                          - 177 * (0.5 * std::log(0.3) + 0.5 * std::log(0.7));
  const VaeLoss loss = ComputePerSampleVaeLoss(output, target, 1.0);
  EXPECT_NEAR(loss.bce[0].item<double>(), expected, 1e-9);
  EXPECT_DOUBLE_EQ(loss.kl[0].item<double>(), 0.0);
}

// The loss terms have their own backward passes; PyTorch's binary_cross_entropy and the KL
// formula through autograd are the references, on reconstructions away from the clamp.
TEST(ComputePerSampleVaeLoss, MatchesPyTorchsBceAndKlWithGradients) {
  torch::manual_seed(31);
  const torch::Tensor reconstruction =
      (torch::rand({5, 180}, torch::kFloat64) * 0.98 + 0.01).requires_grad_(true);
  const torch::Tensor target = torch::rand({5, 180}, torch::kFloat64) * 1.2 - 0.1;  // noisy targets
  const torch::Tensor mu = torch::randn({5, 3}, torch::kFloat64).requires_grad_(true);
  const torch::Tensor logvar = torch::randn({5, 3}, torch::kFloat64).requires_grad_(true);
  const torch::Tensor output_weights = torch::rand({5}, torch::kFloat64);

  const VaeLoss loss = ComputePerSampleVaeLoss({reconstruction, mu, logvar}, target, 0.7);
  const torch::Tensor bce =
      torch::binary_cross_entropy(reconstruction, target, {}, at::Reduction::None).sum(1);
  const torch::Tensor kl = (-0.5 * (1 + logvar - mu.square() - logvar.exp())).sum(1);
  EXPECT_TRUE(torch::allclose(loss.bce, bce, 1e-12, 1e-10));
  EXPECT_TRUE(torch::allclose(loss.kl, kl, 1e-12, 1e-12));

  const auto gradients =
      torch::autograd::grad({(loss.total * output_weights).sum()}, {reconstruction, mu, logvar});
  const auto expected = torch::autograd::grad({((bce + 0.7 * kl) * output_weights).sum()},
                                              {reconstruction, mu, logvar});
  for (std::size_t i = 0; i < gradients.size(); ++i) {
    EXPECT_TRUE(torch::allclose(gradients[i], expected[i], 1e-10, 1e-12)) << "input " << i;
  }
}

TEST(KlPerLatentDimension, CountsDimensionsAboveTheThresholdAsActive) {
  // Dimension 0: KL mu^2 / 2 averaged over (1, 3): 2.5. Dimension 1: 0.005 < 0.01. Dimension 2:
  // logvar = -1 at mu = 0: (e^-1 - 1 + 1) / 2 = 0.18.
  const torch::Tensor mu = torch::tensor({{1.0, 0.1, 0.0}, {3.0, 0.1, 0.0}}, torch::kFloat64);
  const torch::Tensor logvar = torch::tensor({{0.0, 0.0, -1.0}, {0.0, 0.0, -1.0}}, torch::kFloat64);
  const torch::Tensor kl = KlPerLatentDimension(mu, logvar);
  EXPECT_NEAR(kl[0].item<double>(), 2.5, 1e-12);
  EXPECT_NEAR(kl[1].item<double>(), 0.005, 1e-12);
  EXPECT_NEAR(kl[2].item<double>(), 0.5 * std::exp(-1.0), 1e-12);
  EXPECT_EQ(CountActiveLatentDimensions(kl), 2);
  EXPECT_EQ(CountActiveLatentDimensions(kl, 3.0), 0);
}

}  // namespace
}  // namespace colav

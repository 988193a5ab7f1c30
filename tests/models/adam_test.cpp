#include "models/adam.h"

#include <gtest/gtest.h>

namespace colav {
namespace {

TEST(AdamTest, AdamStepsMatchTorchAdam) {
  torch::manual_seed(1);
  std::vector<torch::Tensor> ours = {torch::randn({5, 3}), torch::randn({4})};
  std::vector<torch::Tensor> theirs;
  for (const auto& p : ours) theirs.push_back(p.clone().requires_grad_());
  AdamOptions options;
  options.learning_rate = 0.01;
  Adam optimizer(ours, options);
  torch::optim::Adam reference(theirs, torch::optim::AdamOptions(0.01).eps(1e-5));
  for (int step = 0; step < 5; ++step) {
    std::vector<torch::Tensor> gradients = {torch::randn({5, 3}), torch::randn({4})};
    for (std::size_t i = 0; i < theirs.size(); ++i) theirs[i].mutable_grad() = gradients[i].clone();
    optimizer.Step(gradients);
    reference.step();
  }
  EXPECT_EQ(optimizer.step_count(), 5);
  for (std::size_t i = 0; i < ours.size(); ++i) {
    EXPECT_TRUE(torch::allclose(ours[i], theirs[i].detach(), 1e-5, 1e-6)) << i;
  }
}

TEST(AdamTest, ClippedStepMatchesClipGradNormThenAdam) {
  for (const double max_norm : {0.5, 100.0}) {
    std::vector<torch::Tensor> ours = {torch::randn({7, 3}), torch::randn({9})};
    std::vector<torch::Tensor> theirs;
    for (const auto& p : ours) theirs.push_back(p.clone().requires_grad_());
    const std::vector<torch::Tensor> gradients = {torch::randn({7, 3}), torch::randn({9})};
    for (std::size_t i = 0; i < theirs.size(); ++i) theirs[i].mutable_grad() = gradients[i].clone();

    const double norm = GradientNorm(gradients);
    EXPECT_NEAR(norm, torch::nn::utils::clip_grad_norm_(theirs, max_norm), 1e-5);
    // A large eps makes Adam's first step depend on the gradient's scale, hence on the clipping.
    AdamOptions options;
    options.learning_rate = 0.1;
    options.eps = 0.5;
    Adam optimizer(ours, options);
    optimizer.Step(gradients, ClipCoefficient(norm, max_norm));
    torch::optim::Adam reference(theirs, torch::optim::AdamOptions(0.1).eps(0.5));
    reference.step();
    for (std::size_t i = 0; i < ours.size(); ++i) {
      EXPECT_TRUE(torch::allclose(ours[i], theirs[i].detach(), 1e-5, 1e-6)) << max_norm;
    }
  }
}

TEST(AdamTest, DoubleStepWithAutogradGradientsMatchesTorchAdam) {
  torch::manual_seed(2);
  std::vector<torch::Tensor> ours = {torch::randn({6}).requires_grad_(),
                                     torch::randn({2, 2}).requires_grad_()};
  std::vector<torch::Tensor> theirs;
  for (const auto& p : ours) theirs.push_back(p.detach().clone().requires_grad_());
  AdamOptions options;
  options.learning_rate = 0.01;
  options.eps = 1e-8;
  Adam optimizer(ours, options, AdamArithmetic::kDoubleStep);
  torch::optim::Adam reference(theirs, torch::optim::AdamOptions(0.01));
  for (int step = 0; step < 5; ++step) {
    const torch::Tensor target = torch::randn({6});
    optimizer.ZeroGrad();
    reference.zero_grad();
    (ours[0] - target).square().sum().backward();  // ours[1] gets no gradient: left as it is
    (theirs[0] - target).square().sum().backward();
    optimizer.Step();
    reference.step();
  }
  EXPECT_TRUE(torch::allclose(ours[0].detach(), theirs[0].detach(), 1e-5, 1e-6));
  EXPECT_TRUE(torch::equal(ours[1].detach(), theirs[1].detach()));
}

}  // namespace
}  // namespace colav

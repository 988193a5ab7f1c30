#include <gtest/gtest.h>

#include <cmath>

#include "tests/train/ppo/reference_ppo_loss.h"

namespace colav {
namespace {

const double kUnitGaussianEntropy2d = 2 * (0.5 + 0.5 * std::log(2 * M_PI));

// A batch whose probability ratios are exactly 0.5, 1.0, 1.5 and 1.1 (unit Gaussian at 0).
struct ConstructedBatch {
  torch::Tensor mean = torch::zeros({4, 2});
  torch::Tensor log_std = torch::zeros({2});
  torch::Tensor actions = torch::tensor({{0.1f, -0.2f}, {0.5f, 0.5f}, {-1.0f, 0.3f}, {2.0f, 0.0f}});
  torch::Tensor ratios = torch::tensor({0.5f, 1.0f, 1.5f, 1.1f});
  torch::Tensor advantages = torch::tensor({1.0f, -1.0f, 1.0f, -1.0f});
  torch::Tensor values = torch::tensor({1.0f, 2.0f, 3.0f, 4.0f});
  torch::Tensor returns = torch::ones({4});
  torch::Tensor old_log_probs =
      DiagonalGaussian{mean, log_std}.LogProb(actions) - torch::log(ratios);
};

void ExpectConstructedStats(const PpoLossStats& stats) {
  // min(r A, clip(r) A) = 0.5, -1.0, 1.2 (clipped), -1.1: mean -0.1.
  EXPECT_NEAR(stats.policy_gradient_loss, 0.1, 1e-6);
  EXPECT_NEAR(stats.clip_fraction, 0.5, 1e-9);  // 0.5 and 1.5 lie outside [0.8, 1.2]
  EXPECT_NEAR(stats.value_loss, (0 + 1 + 4 + 9) / 4.0, 1e-6);
  EXPECT_NEAR(stats.entropy_loss, -kUnitGaussianEntropy2d, 1e-6);
  const double kl =
      ((0.5 - 1) - std::log(0.5) + (1.5 - 1) - std::log(1.5) + (1.1 - 1) - std::log(1.1)) / 4;
  EXPECT_NEAR(stats.approx_kl, kl, 1e-6);
  EXPECT_NEAR(stats.loss, 0.1 - 0.01 * kUnitGaussianEntropy2d + 0.5 * 3.5, 1e-6);
}

TEST(PpoLossTest, ClippedObjectiveOnAConstructedBatch) {
  const ConstructedBatch batch;
  PpoLossOptions options;
  options.normalize_advantage = false;
  const PpoLossResult result =
      PpoLoss(DiagonalGaussian{batch.mean, batch.log_std}, batch.values, batch.actions,
              batch.old_log_probs, batch.advantages, batch.returns, options);
  ExpectConstructedStats(result.stats);

  const torch::Tensor mean_t = batch.mean.t().contiguous();
  const PpoMinibatch minibatch{4, batch.actions.data_ptr<float>(),
                               batch.old_log_probs.data_ptr<float>(),
                               batch.advantages.data_ptr<float>(), batch.returns.data_ptr<float>()};
  std::vector<float> d_mean(8), d_value(4), d_log_std(2);
  const PpoLossStats stats = PpoLossGradients(
      mean_t.data_ptr<float>(), batch.log_std.data_ptr<float>(), batch.values.data_ptr<float>(),
      minibatch, options, d_mean.data(), d_log_std.data(), d_value.data());
  ExpectConstructedStats(stats);
  // Sample 2 (r = 1.5 > 1.2 with A > 0) is clipped: no policy gradient through its mean.
  EXPECT_EQ(d_mean[2], 0.0f);
  EXPECT_EQ(d_mean[4 + 2], 0.0f);
  EXPECT_NE(d_mean[0], 0.0f);
}

// The hand-written loss and its gradients on a random minibatch against autograd's.
void ExpectClosedFormMatchesAutograd(bool squashed_actions) {
  torch::manual_seed(4);
  constexpr int B = 32;
  const torch::Tensor mean = (0.5 * torch::randn({B, 2})).requires_grad_();
  const torch::Tensor log_std = (0.3 * torch::randn({2})).requires_grad_();
  const torch::Tensor values = torch::randn({B}).requires_grad_();
  const torch::Tensor actions = mean.detach() + torch::randn({B, 2});
  // Old log-probabilities off by up to +-0.4, so that some ratios are clipped.
  const torch::Tensor old_log_probs =
      DiagonalGaussian{mean.detach(), log_std.detach()}.LogProb(actions) +
      0.8 * (torch::rand({B}) - 0.5);
  const torch::Tensor advantages = 3 * torch::randn({B}) + 1;
  const torch::Tensor returns = torch::randn({B});
  PpoLossOptions options;
  options.squashed_actions = squashed_actions;
  const PpoLossResult result = PpoLoss(DiagonalGaussian{mean, log_std}, values, actions,
                                       old_log_probs, advantages, returns, options);
  result.loss.backward();

  const torch::Tensor mean_t = mean.detach().t().contiguous();
  const torch::Tensor log_std_values = log_std.detach().contiguous();
  const torch::Tensor value_values = values.detach().contiguous();
  const PpoMinibatch minibatch{B, actions.data_ptr<float>(), old_log_probs.data_ptr<float>(),
                               advantages.data_ptr<float>(), returns.data_ptr<float>()};
  std::vector<float> d_mean(2 * B), d_value(B), d_log_std(2);
  const PpoLossStats stats = PpoLossGradients(
      mean_t.data_ptr<float>(), log_std_values.data_ptr<float>(), value_values.data_ptr<float>(),
      minibatch, options, d_mean.data(), d_log_std.data(), d_value.data());
  EXPECT_NEAR(stats.loss, result.stats.loss, 1e-5);
  EXPECT_NEAR(stats.entropy_loss, result.stats.entropy_loss, 1e-5);
  EXPECT_NEAR(stats.clip_fraction, result.stats.clip_fraction, 1e-9);
  EXPECT_GT(stats.clip_fraction, 0.0);
  EXPECT_NEAR(stats.approx_kl, result.stats.approx_kl, 1e-6);
  for (int b = 0; b < B; ++b) {
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(d_mean[j * B + b], mean.grad()[b][j].item<float>(), 1e-6) << b << "," << j;
    }
    EXPECT_NEAR(d_value[b], values.grad()[b].item<float>(), 1e-6) << b;
  }
  for (int j = 0; j < 2; ++j) EXPECT_NEAR(d_log_std[j], log_std.grad()[j].item<float>(), 1e-5);
}

TEST(PpoLossTest, ClosedFormGradientsMatchAutograd) { ExpectClosedFormMatchesAutograd(false); }

TEST(PpoLossTest, SquashedEntropyGradientsMatchAutograd) { ExpectClosedFormMatchesAutograd(true); }

// Samples u with tanh(u) = 0 and +-0.6: log(1 - tanh^2) = 0 and log 0.64 per value.
TEST(PpoLossTest, SquashedEntropyOfHandPickedSamples) {
  const float u = static_cast<float>(std::atanh(0.6));
  const torch::Tensor actions = torch::tensor({{0.0f, u}, {-u, u}});
  const torch::Tensor zeros = torch::zeros({2});
  const torch::Tensor mean_t = torch::zeros({2, 2});
  const torch::Tensor log_probs = DiagonalGaussian{torch::zeros({2, 2}), zeros}.LogProb(actions);
  const PpoMinibatch minibatch{2, actions.data_ptr<float>(), log_probs.data_ptr<float>(),
                               zeros.data_ptr<float>(), zeros.data_ptr<float>()};
  PpoLossOptions options;
  options.squashed_actions = true;
  std::vector<float> d_mean(4), d_value(2), d_log_std(2);
  const PpoLossStats stats =
      PpoLossGradients(mean_t.data_ptr<float>(), zeros.data_ptr<float>(), zeros.data_ptr<float>(),
                       minibatch, options, d_mean.data(), d_log_std.data(), d_value.data());
  // Three of the four values lie at tanh = +-0.6: mean over the 2 samples of 3 log 0.64 / 2.
  EXPECT_NEAR(stats.entropy_loss, -(kUnitGaussianEntropy2d + 1.5 * std::log(0.64)), 1e-6);
}

// The point of squashing: once the std is wide, the entropy bonus pulls it back in. Clipped
// Gaussian actions: the bonus always widens it (d loss / d log std = -ent_coef).
TEST(PpoLossTest, TheSquashedEntropyBonusNarrowsAWideStd) {
  torch::manual_seed(2);
  constexpr int B = 4096;
  for (const double log_std_value : {-1.0, 1.0}) {
    const torch::Tensor log_std = torch::full({2}, log_std_value);
    const torch::Tensor mean = torch::zeros({B, 2});
    const torch::Tensor actions = torch::exp(log_std) * torch::randn({B, 2});
    const torch::Tensor log_probs = DiagonalGaussian{mean, log_std}.LogProb(actions);
    const torch::Tensor zeros = torch::zeros({B});  // no advantage: the entropy term alone
    const torch::Tensor mean_t = mean.t().contiguous();
    const PpoMinibatch minibatch{B, actions.data_ptr<float>(), log_probs.data_ptr<float>(),
                                 zeros.data_ptr<float>(), zeros.data_ptr<float>()};
    for (const bool squashed : {false, true}) {
      PpoLossOptions options;
      options.normalize_advantage = false;
      options.squashed_actions = squashed;
      std::vector<float> d_mean(2 * B), d_value(B), d_log_std(2);
      PpoLossGradients(mean_t.data_ptr<float>(), log_std.data_ptr<float>(), zeros.data_ptr<float>(),
                       minibatch, options, d_mean.data(), d_log_std.data(), d_value.data());
      for (int j = 0; j < 2; ++j) {
        if (!squashed) {
          EXPECT_FLOAT_EQ(d_log_std[j], -options.ent_coef);
        } else if (log_std_value > 0) {
          EXPECT_GT(d_log_std[j], 0.0f) << "std e^" << log_std_value;  // gradient descent narrows
        } else {
          EXPECT_LT(d_log_std[j], 0.0f) << "std e^" << log_std_value;  // and widens a narrow one
        }
      }
    }
  }
}

}  // namespace
}  // namespace colav

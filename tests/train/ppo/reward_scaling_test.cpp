#include "train/ppo/reward_scaling.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace colav {
namespace {

TEST(RunningVarianceTest, MergesABatchByHand) {
  RunningVariance variance;  // mean 0, variance 1, weight 1e-4
  variance.Update({2.0, -1.0});
  // Batch mean 0.5, variance 2.25; merged: mean 0.5 * 2 / 2.0001, M2 = 1e-4 + 4.5 + 0.25 * 1e-4 *
  // 2 / 2.0001.
  EXPECT_DOUBLE_EQ(variance.count, 2.0001);
  EXPECT_DOUBLE_EQ(variance.mean, 1.0 / 2.0001);
  EXPECT_DOUBLE_EQ(variance.variance, (1e-4 + 4.5 + 0.5e-4 / 2.0001) / 2.0001);
}

TEST(RunningVarianceTest, BatchesMergeLikeTheirUnion) {
  RunningVariance pieces, whole;
  pieces.Update({1.0, 5.0, -3.0});
  pieces.Update({10.0, 0.5});
  whole.Update({1.0, 5.0, -3.0, 10.0, 0.5});
  EXPECT_DOUBLE_EQ(pieces.count, whole.count);
  EXPECT_NEAR(pieces.mean, whole.mean, 1e-12);
  EXPECT_NEAR(pieces.variance, whole.variance, 1e-12);
}

// Two worlds, gamma 0.5. World 1's episode ends on step 1, world 0's on step 2. Expected values
// computed by hand from SB3's VecNormalize formulas: returns {2, -1}, then {0.5 * 2 + 4, 0 + 3}
// = {5, 3}, then {0 + 1, 0.5 * 3 - 2000} = {1, -1998.5}; each reward divided by the square root of
// the variance of every return so far (plus 1e-8).
TEST(RewardScalerTest, ScalesByTheSpreadOfTheDiscountedReturns) {
  RewardScaler scaler(2, 0.5);
  const std::vector<std::vector<float>> rewards = {{2.0f, -1.0f}, {4.0f, 3.0f}, {1.0f, -2000.0f}};
  const std::vector<std::vector<std::uint8_t>> dones = {{0, 1}, {1, 0}, {0, 0}};
  const std::vector<std::vector<float>> expected = {
      {1.33334815f, -0.666674078f}, {1.84751403f, 1.38563550f}, {0.00134131033f, -2.68262076f}};
  const std::vector<double> variances = {2.249950001874937, 4.687534370976743, 555829.268170692};
  for (std::size_t t = 0; t < rewards.size(); ++t) {
    float scaled[2];
    scaler.Scale(rewards[t].data(), dones[t].data(), scaled);
    EXPECT_FLOAT_EQ(scaled[0], expected[t][0]) << "step " << t;
    EXPECT_FLOAT_EQ(scaled[1], expected[t][1]) << "step " << t;
    EXPECT_NEAR(scaler.state().return_variance.variance, variances[t], 1e-9 * variances[t]);
  }
  EXPECT_EQ(scaler.state().returns, (std::vector<double>{1.0, -1998.5}));
}

TEST(RewardScalerTest, ClipsAtTenStandardDeviations) {
  RewardScaler scaler(1, 0.99);
  const std::uint8_t done = 0;
  const float zero = 0.0f;
  float scaled = 0.0f;
  for (int t = 0; t < 999; ++t) scaler.Scale(&zero, &done, &scaled);
  // The returns' variance is now about 1e-7: a reward of 1 is about 30 deviations.
  const float one = 1.0f;
  scaler.Scale(&one, &done, &scaled);
  EXPECT_FLOAT_EQ(scaled, 10.0f);
  const float minus_one = -1.0f;
  RewardScaler other(1, 0.99);
  for (int t = 0; t < 999; ++t) other.Scale(&zero, &done, &scaled);
  other.Scale(&minus_one, &done, &scaled);
  EXPECT_FLOAT_EQ(scaled, -10.0f);
}

TEST(RewardScalerTest, RestoreContinuesWhereTheStateWasTaken) {
  RewardScaler first(2, 0.9), second(2, 0.9);
  const float rewards[2] = {1.5f, -0.5f};
  const std::uint8_t dones[2] = {0, 0};
  float scaled_first[2], scaled_second[2];
  first.Scale(rewards, dones, scaled_first);
  second.Restore(first.state());
  first.Scale(rewards, dones, scaled_first);
  second.Scale(rewards, dones, scaled_second);
  EXPECT_EQ(scaled_first[0], scaled_second[0]);
  EXPECT_EQ(scaled_first[1], scaled_second[1]);
  RewardScaler three_worlds(3, 0.9);
  EXPECT_THROW(three_worlds.Restore(first.state()), std::invalid_argument);
}

}  // namespace
}  // namespace colav

#include "train/ppo/learning_rate_schedule.h"

#include <gtest/gtest.h>

#include "models/adam.h"
#include "src/error.h"

namespace colav {
namespace {

TEST(LearningRateScheduleTest, ConstantKeepsTheInitialRate) {
  for (const std::int64_t step : {0, 8192, 3'000'000, 3'006'464}) {
    EXPECT_EQ(ScheduledLearningRate(LearningRateSchedule::kConstant, 2e-4, step, 3'000'000), 2e-4);
  }
}

TEST(LearningRateScheduleTest, LinearFallsWithTheProgressRemaining) {
  const auto rate = [](std::int64_t step) {
    return ScheduledLearningRate(LearningRateSchedule::kLinear, 4e-4, step, 1'000'000);
  };
  EXPECT_DOUBLE_EQ(rate(0), 4e-4);
  EXPECT_DOUBLE_EQ(rate(250'000), 3e-4);
  EXPECT_DOUBLE_EQ(rate(500'000), 2e-4);
  EXPECT_DOUBLE_EQ(rate(1'000'000), 0.0);
  // SB3's last rollout overshoots the total: the rate stays at 0 instead of turning negative.
  EXPECT_DOUBLE_EQ(rate(1'008'192), 0.0);
}

TEST(LearningRateScheduleTest, NamesRoundTripAndUnknownNamesAreRefused) {
  for (const auto schedule : {LearningRateSchedule::kConstant, LearningRateSchedule::kLinear}) {
    EXPECT_EQ(ParseLearningRateSchedule(LearningRateScheduleName(schedule)), schedule);
  }
  EXPECT_THROW(ParseLearningRateSchedule("cosine"), UserError);
}

TEST(LearningRateScheduleTest, AdamTakesTheNewRateAndKeepsItsMoments) {
  // Two optimisers see the same gradients; one has its rate halved before the second step. The
  // second step's displacement must be exactly half the other's (same moments, same t).
  std::vector<torch::Tensor> full = {torch::tensor({1.0f, -2.0f})};
  std::vector<torch::Tensor> halved = {full[0].clone()};
  AdamOptions options;
  options.learning_rate = 0.1;
  Adam full_rate(full, options);
  Adam halved_rate(halved, options);
  const std::vector<torch::Tensor> gradients = {torch::tensor({0.5f, 0.25f})};
  full_rate.Step(gradients);
  halved_rate.Step(gradients);
  const torch::Tensor before = full[0].clone();
  halved_rate.set_learning_rate(0.05);
  full_rate.Step(gradients);
  halved_rate.Step(gradients);
  EXPECT_TRUE(torch::allclose(halved[0] - before, 0.5 * (full[0] - before), 1e-6, 1e-7));
  EXPECT_EQ(halved_rate.step_count(), 2);
}

}  // namespace
}  // namespace colav

#include "train/ppo/critic_warmup.h"

#include <gtest/gtest.h>

namespace colav {
namespace {

constexpr std::int64_t kRollout = 8192;  // 8 worlds x 1,024 steps

TEST(CriticWarmupTest, NoWarmupTrainsEverythingFromTheFirstUpdate) {
  for (const std::int64_t step : {kRollout, 2 * kRollout, 366 * kRollout}) {
    EXPECT_EQ(UpdatePhaseAt(step, kRollout, 0), UpdatePhase::kAll) << step;
  }
}

TEST(CriticWarmupTest, RolloutsEndingAtOrBeforeTheWarmupTrainTheCriticAlone) {
  // 500,000 steps: rollouts 1-61 end at or before it (61 x 8,192 = 499,712); the 62nd, ending at
  // 507,904, is the actor's first, and every later one trains everything.
  constexpr std::int64_t kWarmup = 500'000;
  EXPECT_EQ(UpdatePhaseAt(kRollout, kRollout, kWarmup), UpdatePhase::kCriticOnly);
  EXPECT_EQ(UpdatePhaseAt(61 * kRollout, kRollout, kWarmup), UpdatePhase::kCriticOnly);
  EXPECT_EQ(UpdatePhaseAt(62 * kRollout, kRollout, kWarmup), UpdatePhase::kActorJoins);
  EXPECT_EQ(UpdatePhaseAt(63 * kRollout, kRollout, kWarmup), UpdatePhase::kAll);
  // A warm-up that ends on a rollout's last step includes that rollout.
  EXPECT_EQ(UpdatePhaseAt(2 * kRollout, kRollout, 2 * kRollout), UpdatePhase::kCriticOnly);
  EXPECT_EQ(UpdatePhaseAt(3 * kRollout, kRollout, 2 * kRollout), UpdatePhase::kActorJoins);
}

TEST(CriticWarmupTest, AWarmupShorterThanARolloutHoldsNoUpdate) {
  EXPECT_EQ(UpdatePhaseAt(kRollout, kRollout, 100), UpdatePhase::kActorJoins);
  EXPECT_EQ(UpdatePhaseAt(2 * kRollout, kRollout, 100), UpdatePhase::kAll);
}

}  // namespace
}  // namespace colav

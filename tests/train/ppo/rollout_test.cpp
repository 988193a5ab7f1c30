// Which episode ends continue their return with gamma * V(final observation), and what the
// policy sees with normalised navigation values.
#include "train/ppo/rollout.h"

#include <gtest/gtest.h>

#include <vector>

namespace colav {
namespace {

TEST(BootstrapsFromFinalObservation, OnlyATimeOutThatDidNotAlsoTerminate) {
  // Stable-Baselines3: TimeLimit.truncated = truncated and not terminated.
  EXPECT_TRUE(BootstrapsFromFinalObservation(/*terminated=*/false, /*truncated=*/true, false));
  EXPECT_FALSE(BootstrapsFromFinalObservation(true, true, false));  // collided on the last step
  EXPECT_FALSE(BootstrapsFromFinalObservation(true, false, false));
  EXPECT_FALSE(BootstrapsFromFinalObservation(false, false, false));
}

TEST(BootstrapsFromFinalObservation, NeverWhenTimeOutsAreTerminal) {
  for (const bool terminated : {false, true}) {
    for (const bool truncated : {false, true}) {
      EXPECT_FALSE(BootstrapsFromFinalObservation(terminated, truncated, true));
    }
  }
}

// The first sample of a run: the worlds' reset observations, their navigation values normalised
// by the moments of those same observations (SB3 updates the moments before normalising).
TEST(RolloutCollectorTest, TheBufferHoldsNormalisedNavigationValues) {
  constexpr int kWorlds = 3;
  constexpr std::uint64_t kSeed = 11;
  const EnvironmentConfig config;
  BatchedEnvironment raw(config, kWorlds, 1, kSeed);
  raw.Reset();
  const int width = raw.observation_size();
  std::vector<float> expected(raw.observations(), raw.observations() + kWorlds * width);
  NavigationNormalizer by_hand;
  by_hand.Update(expected.data(), kWorlds, width);
  by_hand.Normalize(expected.data(), kWorlds, width);

  for (const bool normalize : {true, false}) {
    RolloutRules rules;
    rules.normalize_navigation = normalize;
    RolloutCollector collector(config, kWorlds, 1, kSeed, rules);
    FastActorCritic policy(ActorCritic(ActorCriticOptions{}), kWorlds);
    RolloutBuffer buffer(1, kWorlds, width);
    collector.Collect(policy, torch::zeros({1, kWorlds, kActionSize}), buffer,
                      [](const std::vector<FinishedEpisode>&) { return true; });
    const std::vector<float> seen(buffer.observations(0), buffer.observations(0) + kWorlds * width);
    EXPECT_EQ(seen, normalize ? expected
                              : std::vector<float>(raw.observations(),
                                                   raw.observations() + kWorlds * width));
    EXPECT_EQ(collector.navigation_normalization().has_value(), normalize);
  }
}

}  // namespace
}  // namespace colav

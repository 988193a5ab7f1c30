// Which episode ends continue their return with gamma * V(final observation), what the policy sees
// with normalised navigation values, and which actions the worlds get.
#include "train/ppo/rollout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
    RolloutCollector collector(config, std::vector<TrainingScenarioConfig>(kWorlds), 1, kSeed,
                               rules);
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

// The buffer keeps the Gaussian samples; the worlds get them clipped, or squashed by tanh.
TEST(RolloutCollectorTest, TheWorldsGetClippedOrSquashedSamples) {
  constexpr int kWorlds = 2;
  constexpr std::uint64_t kSeed = 5;
  const EnvironmentConfig config;
  for (const bool squash : {false, true}) {
    RolloutCollector collector(config, std::vector<TrainingScenarioConfig>(kWorlds), 1, kSeed,
                               RolloutRules{});
    ActorCriticOptions options;
    options.squash_actions = squash;
    FastActorCritic policy(ActorCritic(options), kWorlds);
    BatchedEnvironment by_hand(config, kWorlds, 1, kSeed);
    const int width = by_hand.observation_size();
    RolloutBuffer buffer(2, kWorlds, width);
    // Samples near +-1.5 (std 1): clipping gives +-1, tanh about +-0.9.
    const torch::Tensor noise =
        torch::tensor({1.5f, -1.5f, -1.5f, 1.5f}).repeat({2}).reshape({2, kWorlds, kActionSize});
    collector.Collect(policy, noise, buffer,
                      [](const std::vector<FinishedEpisode>&) { return true; });
    std::vector<float> actions(kWorlds * kActionSize);
    for (int k = 0; k < kWorlds * kActionSize; ++k) {
      EXPECT_NEAR(buffer.actions(0)[k], noise[0].flatten()[k].item<float>(), 0.1);
      actions[k] =
          squash ? std::tanh(buffer.actions(0)[k]) : std::clamp(buffer.actions(0)[k], -1.0f, 1.0f);
    }
    by_hand.Reset();
    by_hand.Step(actions.data());
    EXPECT_EQ(std::vector<float>(buffer.observations(1), buffer.observations(1) + kWorlds * width),
              std::vector<float>(by_hand.observations(), by_hand.observations() + kWorlds * width))
        << (squash ? "squashed" : "clipped");
  }
}

}  // namespace
}  // namespace colav

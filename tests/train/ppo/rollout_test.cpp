// Which episode ends continue their return with gamma * V(final observation), what the policy sees
// with normalised navigation values, which actions the worlds get, and what a curriculum's switch
// does to the worlds.
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
// A privileged critic's first sample: the buffer keeps the worlds' critic observations, and the
// values are those of the critic reading them.
TEST(RolloutCollectorTest, APrivilegedCriticsBufferHoldsTheWorldsCriticObservations) {
  constexpr int kWorlds = 8;
  constexpr std::uint64_t kSeed = 11;
  constexpr int kVessels = 4;
  const EnvironmentConfig config;
  BatchedEnvironment raw(config, kWorlds, 1, kSeed);
  raw.ObserveVesselsForCritic(kVessels);
  raw.Reset();
  const int width = raw.observation_size();
  const int critic_width = raw.critic_observation_size();
  const std::vector<float> expected(raw.critic_observations(),
                                    raw.critic_observations() + kWorlds * critic_width);
  int present = 0;
  for (int i = 0; i < kWorlds * kVessels; ++i) present += expected[i * kCriticValuesPerVessel] > 0;
  ASSERT_GT(present, 0) << "some world starts with a vessel within range";

  RolloutRules rules;
  rules.critic_vessels = kVessels;
  RolloutCollector collector(config, std::vector<TrainingScenarioConfig>(kWorlds), 1, kSeed, rules);
  ActorCriticOptions options;
  options.critic_vessels = kVessels;
  FastActorCritic policy(ActorCritic(options), kWorlds);
  RolloutBuffer buffer(1, kWorlds, width, 0, critic_width);
  collector.Collect(policy, torch::zeros({1, kWorlds, kActionSize}), buffer,
                    [](const std::vector<FinishedEpisode>&) { return true; });
  EXPECT_EQ(std::vector<float>(buffer.critic_observations(0),
                               buffer.critic_observations(0) + kWorlds * critic_width),
            expected);
  std::vector<float> mean(kWorlds * kActionSize), value(kWorlds), blind_value(kWorlds);
  policy.Predict(buffer.observations(0), kWorlds, mean.data(), value.data(), nullptr,
                 expected.data());
  EXPECT_EQ(std::vector<float>(buffer.values(0), buffer.values(0) + kWorlds), value);
  const std::vector<float> no_vessels(expected.size(), 0.0f);
  policy.Predict(buffer.observations(0), kWorlds, mean.data(), blind_value.data(), nullptr,
                 no_vessels.data());
  EXPECT_NE(blind_value, value);
}

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

// A curriculum's switch: every world leaves its episode and starts its next one in its new kind,
// as a fresh environment of that kind restored to that episode shows, with its return restarted.
TEST(RolloutCollectorTest, ReplacedWorldsStartTheirNextEpisodesInTheirNewKind) {
  constexpr int kWorlds = 2;
  constexpr std::uint64_t kSeed = 5;
  const EnvironmentConfig config;
  RolloutRules rules;
  rules.scale_rewards = true;
  rules.gamma = 0.99;
  RolloutCollector collector(config, std::vector<TrainingScenarioConfig>(kWorlds), 1, kSeed, rules);
  FastActorCritic policy(ActorCritic(ActorCriticOptions{}), kWorlds);
  const int width = ObservationSize(config);
  RolloutBuffer buffer(4, kWorlds, width);
  const auto keep_going = [](const std::vector<FinishedEpisode>&) { return true; };
  collector.Collect(policy, torch::zeros({4, kWorlds, kActionSize}), buffer, keep_going);
  ASSERT_EQ(collector.world_histories()[0].actions.size(), 4U * kActionSize);

  TrainingScenarioConfig crowded;
  crowded.num_static = 40;
  const std::vector<TrainingScenarioConfig> crowded_worlds(kWorlds, crowded);
  collector.ReplaceWorlds(crowded_worlds);
  for (const WorldHistory& history : collector.world_histories()) {
    EXPECT_EQ(history.episode, 1U);
    EXPECT_TRUE(history.actions.empty());
  }
  EXPECT_EQ(collector.reward_scaling().returns, std::vector<double>(kWorlds, 0.0));

  BatchedEnvironment expected(config, crowded_worlds, 1, kSeed);
  expected.Restore(std::vector<WorldHistory>(kWorlds, WorldHistory{1, {}}));
  RolloutBuffer next(1, kWorlds, width);
  collector.Collect(policy, torch::zeros({1, kWorlds, kActionSize}), next, keep_going);
  EXPECT_TRUE(std::equal(expected.observations(), expected.observations() + kWorlds * width,
                         next.observations(0)));
}

// A recurrent policy: the buffer records each world's state before every step, 0 where its
// episode starts (the worlds time out after 3 steps here) and otherwise the state the policy left
// after the world's previous step; a curriculum's switch restarts every state.
TEST(RolloutCollectorTest, ARecurrentPolicysStatesRunThroughEpisodesAndRestartAtTheirEnds) {
  constexpr int kWorlds = 2, kSteps = 8, kState = 3;
  constexpr std::uint64_t kSeed = 5;
  EnvironmentConfig config;
  config.max_steps = 3;
  RolloutCollector collector(config, std::vector<TrainingScenarioConfig>(kWorlds), 1, kSeed,
                             RolloutRules{});
  ActorCriticOptions options;
  options.recurrent_size = kState;
  ActorCritic model(options);
  FastActorCritic policy(model, kWorlds);
  FastActorCritic by_hand(model, 1);
  const int width = ObservationSize(config);
  RolloutBuffer buffer(kSteps, kWorlds, width, kState);
  collector.Collect(policy, torch::randn({kSteps, kWorlds, kActionSize}), buffer,
                    [](const std::vector<FinishedEpisode>&) { return true; });
  int starts = 0;
  for (int t = 0; t < kSteps; ++t) {
    for (int e = 0; e < kWorlds; ++e) {
      const float* recorded = buffer.states(t) + e * kState;
      std::vector<float> expected(kState, 0.0f);
      if (t > 0 && buffer.dones(t - 1)[e] == 0) {
        expected.assign(buffer.states(t - 1) + e * kState, buffer.states(t - 1) + (e + 1) * kState);
        float mean[kActionSize], value;
        by_hand.Predict(buffer.observations(t - 1) + e * width, 1, mean, &value, expected.data());
      }
      starts += t > 0 && buffer.dones(t - 1)[e] != 0;
      for (int j = 0; j < kState; ++j) {
        EXPECT_NEAR(recorded[j], expected[j], 1e-6) << "step " << t << " world " << e;
      }
      if (t > 0 && buffer.dones(t - 1)[e] == 0) {
        EXPECT_GT(std::abs(recorded[0]) + std::abs(recorded[1]) + std::abs(recorded[2]), 0.0f);
      }
    }
  }
  EXPECT_EQ(starts, 2 * kWorlds);  // after steps 2 and 5
  collector.ReplaceWorlds(std::vector<TrainingScenarioConfig>(kWorlds));
  EXPECT_EQ(collector.policy_states(), std::vector<float>(kWorlds * kState, 0.0f));
}

}  // namespace
}  // namespace colav

// Restoring a batched environment from its worlds' histories (what a PPO checkpoint saves):
// replaying the recorded actions from each episode's start rebuilds every world bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "env/batched_environment.h"

namespace colav {
namespace {

constexpr int kWorlds = 4;

EnvironmentConfig SeventyStepEpisodes() {
  EnvironmentConfig config;
  config.max_steps = 70;  // episodes end within the test, and some are cut mid-episode
  return config;
}

// Random actions partly outside [-1, 1], so that clipping is part of what is recorded.
std::vector<float> RandomActions(std::mt19937& random) {
  std::uniform_real_distribution<float> uniform(-1.3f, 1.3f);
  std::vector<float> actions(kWorlds * kActionSize);
  for (float& action : actions) action = uniform(random);
  return actions;
}

void ExpectSameBytes(const float* a, const float* b, std::size_t count) {
  EXPECT_EQ(std::memcmp(a, b, count * sizeof(float)), 0);
}

void ExpectSameStep(const BatchedEnvironment& a, const BatchedEnvironment& b) {
  ExpectSameBytes(a.observations(), b.observations(), kWorlds * kObservationSize);
  ExpectSameBytes(a.rewards(), b.rewards(), kWorlds);
  for (int i = 0; i < kWorlds; ++i) {
    ASSERT_EQ(a.terminated()[i], b.terminated()[i]);
    ASSERT_EQ(a.truncated()[i], b.truncated()[i]);
    ASSERT_EQ(a.finished_episodes()[i].has_value(), b.finished_episodes()[i].has_value());
    if (!a.finished_episodes()[i]) continue;
    const EpisodeMetrics& x = *a.finished_episodes()[i];
    const EpisodeMetrics& y = *b.finished_episodes()[i];
    // The accumulators (reward, cross-track error) are rebuilt exactly too.
    EXPECT_EQ(x.cumulative_reward, y.cumulative_reward);
    EXPECT_EQ(x.mean_abs_cte, y.mean_abs_cte);
    EXPECT_EQ(x.progress, y.progress);
    EXPECT_EQ(x.steps, y.steps);
    EXPECT_EQ(x.collision, y.collision);
  }
}

TEST(WorldHistory, RestoredWorldsContinueBitForBit) {
  std::mt19937 random(5);
  BatchedEnvironment original(SeventyStepEpisodes(), kWorlds, 2, 17);
  original.Reset();
  for (int t = 0; t < 150; ++t) original.Step(RandomActions(random).data());
  std::uint64_t episodes_started = 0;
  for (const WorldHistory& history : original.histories()) episodes_started += history.episode;
  ASSERT_GT(episodes_started, 0U);  // the histories start in later episodes than the first

  BatchedEnvironment restored(SeventyStepEpisodes(), kWorlds, 1, 17);  // another thread count
  restored.Reset();
  restored.Restore(original.histories());
  ExpectSameBytes(original.observations(), restored.observations(), kWorlds * kObservationSize);
  for (int t = 0; t < 200; ++t) {
    const std::vector<float> actions = RandomActions(random);
    original.Step(actions.data());
    restored.Step(actions.data());
    ExpectSameStep(original, restored);
    if (HasFailure()) return;
  }
}

TEST(WorldHistory, RestoreRefusesHistoriesThatCannotBeThisEnvironments) {
  BatchedEnvironment envs(SeventyStepEpisodes(), kWorlds, 1, 17);
  envs.Reset();
  std::vector<WorldHistory> histories = envs.histories();
  EXPECT_THROW(envs.Restore({histories.begin(), histories.end() - 1}), std::invalid_argument);
  histories[1].actions.assign(2 * 80, 0.0);  // longer than an episode lasts
  EXPECT_THROW(envs.Restore(histories), std::invalid_argument);
  histories[1].actions.assign(3, 0.0);  // half an action
  EXPECT_THROW(envs.Restore(histories), std::invalid_argument);
  histories[1].actions.assign(2, std::nan(""));
  EXPECT_THROW(envs.Restore(histories), std::invalid_argument);
}

}  // namespace
}  // namespace colav

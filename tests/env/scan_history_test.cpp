// The scan history (env.scan_history): earlier scans follow the current one in the observation,
// newest first, scan_history_interval steps apart, the episode's first scan while there is none.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "env/batched_environment.h"
#include "env/environment.h"
#include "env/training_scenario.h"

namespace colav {
namespace {

constexpr int kHistory = 2;
constexpr int kInterval = 3;

EnvironmentConfig HistoryConfig() {
  EnvironmentConfig config;
  config.scan_history = kHistory;
  config.scan_history_interval = kInterval;
  return config;
}

std::vector<float> Scan(const std::vector<float>& observation, int k) {
  const auto begin = observation.begin() + kNavigationSize + k * kNumRays;
  return {begin, begin + kNumRays};
}

// The observations of `steps` steps (reset included) of training episode `seed` under `config`,
// turning hard left so that the scans change from step to step.
std::vector<std::vector<float>> Observations(const EnvironmentConfig& config, int steps) {
  Environment env(config, std::make_shared<TrainingScenarioGenerator>());
  std::vector<std::vector<float>> observations(steps + 1,
                                               std::vector<float>(ObservationSize(config)));
  env.Reset(7, observations[0].data());
  const double action[kActionSize] = {1.0, 1.0};
  for (int t = 1; t <= steps; ++t) {
    const StepResult result = env.Step(action, observations[t].data());
    EXPECT_FALSE(result.terminated || result.truncated) << "the episode must outlast the test";
  }
  return observations;
}

TEST(ScanHistory, ObservationSizeCountsEveryScan) {
  EXPECT_EQ(ObservationSize(EnvironmentConfig{}), kObservationSize);
  EXPECT_EQ(ObservationSize(HistoryConfig()), 6 + 3 * 180);
}

TEST(ScanHistory, EarlierScansAreTheScansOfEarlierSteps) {
  constexpr int kSteps = 12;
  const auto plain = Observations(EnvironmentConfig{}, kSteps);
  const auto stacked = Observations(HistoryConfig(), kSteps);
  for (int t = 0; t <= kSteps; ++t) {
    EXPECT_TRUE(std::equal(plain[t].begin(), plain[t].end(), stacked[t].begin()))
        << "the first 186 values are the paper's observation, step " << t;
    for (int k = 1; k <= kHistory; ++k) {
      const int earlier = std::max(0, t - k * kInterval);
      EXPECT_EQ(Scan(stacked[t], k), Scan(plain[earlier], 0)) << "step " << t << ", scan " << k;
    }
  }
  EXPECT_NE(Scan(plain[kSteps], 0), Scan(plain[0], 0)) << "the scans must change to test this";
}

TEST(ScanHistory, AResetForgetsThePreviousEpisode) {
  Environment env(HistoryConfig(), std::make_shared<TrainingScenarioGenerator>());
  std::vector<float> observation(ObservationSize(HistoryConfig()));
  env.Reset(7, observation.data());
  const double action[kActionSize] = {1.0, 1.0};
  for (int t = 0; t < 10; ++t) env.Step(action, observation.data());
  env.Reset(8, observation.data());
  for (int k = 1; k <= kHistory; ++k) EXPECT_EQ(Scan(observation, k), Scan(observation, 0));
}

TEST(ScanHistory, BatchedRowsHoldTheWholeObservation) {
  BatchedEnvironment envs(HistoryConfig(), 2, 2, 3);
  ASSERT_EQ(envs.observation_size(), ObservationSize(HistoryConfig()));
  envs.Reset();
  const std::vector<float> actions(2 * kActionSize, 0.5f);
  for (int t = 0; t < 2 * kInterval; ++t) envs.Step(actions.data());
  for (int world = 0; world < 2; ++world) {
    const float* row = envs.observations() + world * envs.observation_size();
    const std::vector<float> current(row + kNavigationSize, row + kNavigationSize + kNumRays);
    const std::vector<float> oldest(row + kNavigationSize + kHistory * kNumRays,
                                    row + envs.observation_size());
    EXPECT_NE(current, oldest) << "world " << world << " moved for " << 2 * kInterval << " steps";
  }
}

}  // namespace
}  // namespace colav

// Batched environment: auto-reset, final observations, determinism across thread counts.
#include "env/batched_environment.h"

#include <gtest/gtest.h>

#include "env/environment.h"

namespace colav {
namespace {

struct BatchRun {
  std::vector<float> observations;
  std::vector<float> rewards;
  int finished = 0;
};

BatchRun RunBatch(int num_threads, int steps) {
  BatchedEnvironment envs(EnvironmentConfig{}, 4, num_threads, 9);
  envs.Reset();
  std::vector<float> actions(4 * kActionSize);
  BatchRun run;
  for (int t = 0; t < steps; ++t) {
    for (int i = 0; i < 4; ++i) {
      actions[i * 2] = 1.0f;
      actions[i * 2 + 1] = (i % 2 == 0 ? 1.0f : -0.3f);
    }
    envs.Step(actions.data());
    run.observations.insert(run.observations.end(), envs.observations(),
                            envs.observations() + 4 * kObservationSize);
    run.rewards.insert(run.rewards.end(), envs.rewards(), envs.rewards() + 4);
    for (int i = 0; i < 4; ++i) run.finished += envs.finished_episodes()[i].has_value();
  }
  return run;
}

TEST(BatchedEnvironment, SameResultOnOneOrTwoThreads) {
  const BatchRun one = RunBatch(1, 300);
  const BatchRun two = RunBatch(2, 300);
  EXPECT_EQ(one.observations, two.observations);
  EXPECT_EQ(one.rewards, two.rewards);
}

TEST(BatchedEnvironment, AutoResetHandsBackFinalObservation) {
  EnvironmentConfig config;
  config.max_steps = 5;  // every episode is truncated after 5 steps
  BatchedEnvironment envs(config, 3, 2, 1);
  envs.Reset();
  const std::vector<float> first(envs.observations(), envs.observations() + 3 * kObservationSize);
  std::vector<float> actions(3 * kActionSize, 0.0f);
  for (int t = 1; t <= 5; ++t) {
    envs.Step(actions.data());
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(envs.truncated()[i], t == 5);
      EXPECT_EQ(envs.finished_episodes()[i].has_value(), t == 5);
    }
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(envs.finished_episodes()[i]->steps, 5);
    EXPECT_TRUE(envs.finished_episodes()[i]->truncated);
    // The new episode's world differs from the first one; the final observation is not the
    // reset observation.
    const float* final_obs = envs.final_observations() + i * kObservationSize;
    const float* reset_obs = envs.observations() + i * kObservationSize;
    EXPECT_NE(std::vector<float>(final_obs, final_obs + kObservationSize),
              std::vector<float>(reset_obs, reset_obs + kObservationSize));
    EXPECT_NE(std::vector<float>(reset_obs, reset_obs + kObservationSize),
              std::vector<float>(first.begin() + i * kObservationSize,
                                 first.begin() + (i + 1) * kObservationSize));
  }
}

// Short episodes: most steps swap in a next episode prepared by the worker (or reset inline when
// it is not ready), and Reset with and without a seed restarts or moves on.
std::vector<float> ShortEpisodesRun(int num_threads) {
  EnvironmentConfig config;
  config.max_steps = 7;
  BatchedEnvironment envs(config, 5, num_threads, 3);
  std::vector<float> observations(5 * kObservationSize);
  std::vector<float> final_observations(observations.size());
  std::vector<float> rewards(5);
  std::vector<std::uint8_t> terminated(5);
  std::vector<std::uint8_t> truncated(5);
  const BatchedOutputs outputs{observations.data(), final_observations.data(), rewards.data(),
                               terminated.data(), truncated.data()};
  std::vector<float> run;
  const std::vector<double> actions(5 * kActionSize, 0.5);
  for (const std::optional<std::uint64_t> seed :
       {std::optional<std::uint64_t>(3), std::optional<std::uint64_t>(),
        std::optional<std::uint64_t>(4)}) {
    envs.Reset(seed, outputs);
    run.insert(run.end(), observations.begin(), observations.end());
    for (int t = 0; t < 60; ++t) {
      envs.Step(actions.data(), outputs);
      run.insert(run.end(), observations.begin(), observations.end());
      run.insert(run.end(), rewards.begin(), rewards.end());
    }
  }
  return run;
}

TEST(BatchedEnvironment, PreparedEpisodesGiveTheSameResultsAsResets) {
  const std::vector<float> one = ShortEpisodesRun(1);
  EXPECT_EQ(one, ShortEpisodesRun(2));
  EXPECT_EQ(one, ShortEpisodesRun(3));
}

TEST(BatchedEnvironment, ResetWithASeedStartsOverWithoutMovesOn) {
  BatchedEnvironment envs(EnvironmentConfig{}, 2, 2, 5);
  envs.Reset();
  const std::vector<float> first(envs.observations(), envs.observations() + kObservationSize);
  envs.Reset();
  const std::vector<float> next(envs.observations(), envs.observations() + kObservationSize);
  envs.Reset(5);
  EXPECT_EQ(first, std::vector<float>(envs.observations(), envs.observations() + kObservationSize));
  EXPECT_NE(first, next);
}

// The reset observation of world `world`'s first episode, generated alone.
std::vector<float> FirstObservation(const TrainingScenarioConfig& worlds, std::uint64_t seed,
                                    int world) {
  Environment env(EnvironmentConfig{}, std::make_shared<TrainingScenarioGenerator>(worlds));
  std::vector<float> observation(kObservationSize);
  env.Reset(TrainingEpisodeSeed(seed, world, 0), observation.data());
  return observation;
}

TEST(BatchedEnvironment, EachWorldTrainsInItsOwnScenario) {
  TrainingScenarioConfig crowded;
  crowded.num_static = 30;
  crowded.static_displacement_sd = 20.0;
  const std::vector<TrainingScenarioConfig> scenarios = {crowded, crowded, {}};
  BatchedEnvironment envs(EnvironmentConfig{}, scenarios, 1, 7);
  envs.Reset();
  for (int world = 0; world < 3; ++world) {
    const std::vector<float> row(envs.observations() + world * kObservationSize,
                                 envs.observations() + (world + 1) * kObservationSize);
    EXPECT_EQ(row, FirstObservation(scenarios[world], 7, world)) << world;
  }
  // The crowded worlds differ from the paper's world of the same seed.
  EXPECT_NE(std::vector<float>(envs.observations(), envs.observations() + kObservationSize),
            FirstObservation({}, 7, 0));
}

}  // namespace
}  // namespace colav

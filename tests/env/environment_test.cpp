// Reward, termination and truncation rules, observations, determinism of the environment.
#include "env/environment.h"

#include <gtest/gtest.h>

#include <cmath>

#include "env/angles.h"
#include "env/reward.h"
#include "env/scenario_file.h"
#include "env/training_scenario.h"

namespace colav {
namespace {

Scenario StraightScenario(double length = 300.0) {
  Scenario s;
  s.name = "straight";
  s.waypoints = {{0.0, 0.0}, {length, 0.0}};
  return s;
}

Environment MakeEnvironment(const Scenario& scenario, EnvironmentConfig config = {}) {
  return Environment(config, std::make_shared<FixedScenarioSource>(scenario));
}

TEST(Reward, FormulaAndCollision) {
  EXPECT_DOUBLE_EQ(PathReward(0.57, 0.0, 0.0, false), 1.0);
  EXPECT_DOUBLE_EQ(PathReward(0.0, 0.3, 10.0, false), -1.0);
  EXPECT_NEAR(PathReward(0.285, kPi / 2.0, 100.0, false), 0.5 * 1.0 / 2.0 - 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(PathReward(0.57, 0.0, 0.0, true), -1000.0);
}

TEST(Environment, ObservationLayoutAtReset) {
  Scenario s = StraightScenario();
  s.vessel_position = {10.0, 5.0};
  s.vessel_heading = 0.3;
  s.vessel_velocity = {0.2, 0.01, 0.02};
  s.static_obstacles = {{{60.0, 5.0}, 10.0}};
  Environment env = MakeEnvironment(s);
  std::vector<float> obs(kObservationSize);
  env.Reset(0, obs.data());
  EXPECT_FLOAT_EQ(obs[0], 0.2f);
  EXPECT_FLOAT_EQ(obs[1], 0.01f);
  EXPECT_FLOAT_EQ(obs[2], 0.02f);
  EXPECT_FLOAT_EQ(obs[3], -0.05f);  // cte / 100
  EXPECT_NEAR(obs[4], std::atan2(-5.0, 150.0) - 0.3, 1e-6);
  EXPECT_NEAR(obs[5], -0.3, 1e-6);
  // The circle 50 m ahead of the vessel position along +x is at relative angle -0.3 rad.
  double nearest = 0.0;
  for (int i = 0; i < kNumRays; ++i) nearest = std::max<double>(nearest, obs[kNavigationSize + i]);
  EXPECT_NEAR(nearest, 1.0 - 40.0 / 150.0, 0.01);
}

TEST(Environment, GoalByDistanceEndsEpisode) {
  Scenario s = StraightScenario(100.0);
  s.vessel_position = {95.5, 0.0};
  Environment env = MakeEnvironment(
      s, EnvironmentConfig{ClosenessTransform::kLinear, false, 2000, 5.0, 2.0, -2000.0});
  std::vector<float> obs(kObservationSize);
  env.Reset(0, obs.data());
  const double action[2] = {-1.0, 0.0};  // no thrust: stays within 5 m
  const StepResult result = env.Step(action, obs.data());
  EXPECT_TRUE(result.goal_reached);
  EXPECT_TRUE(result.terminated);
  EXPECT_FALSE(result.truncated);
  ASSERT_TRUE(result.episode.has_value());
  EXPECT_EQ(result.episode->steps, 1);
  EXPECT_TRUE(result.episode->goal_reached);
}

TEST(Environment, GoalByProgress) {
  Scenario s = StraightScenario(1000.0);
  s.vessel_position = {990.5, 40.0};  // 40 m to the side, but progress >= 0.99
  Environment env = MakeEnvironment(s);
  std::vector<float> obs(kObservationSize);
  env.Reset(0, obs.data());
  const double action[2] = {-1.0, 0.0};
  EXPECT_TRUE(env.Step(action, obs.data()).goal_reached);
}

TEST(Environment, CollisionEndsEpisodeWithPenalty) {
  Scenario s = StraightScenario();
  s.static_obstacles = {{{2.49, 0.0}, 1.2}};  // clearance 0.035 m; the first step closes it
  Environment env = MakeEnvironment(s);
  std::vector<float> obs(kObservationSize);
  env.Reset(0, obs.data());
  const double action[2] = {1.0, 0.0};
  const StepResult result = env.Step(action, obs.data());
  EXPECT_TRUE(result.collision);
  EXPECT_TRUE(result.terminated);
  EXPECT_DOUBLE_EQ(result.reward, -1000.0);
  ASSERT_TRUE(result.episode.has_value());
  EXPECT_TRUE(result.episode->collision);
}

TEST(Environment, TruncationAfterMaxStepsAndRewardFloor) {
  Scenario s = StraightScenario();
  s.vessel_heading = kPi;  // pointing away, no thrust: reward -1 per step
  EnvironmentConfig config;
  config.max_steps = 50;
  config.test_mode = true;
  Environment env = MakeEnvironment(s, config);
  std::vector<float> obs(kObservationSize);
  env.Reset(0, obs.data());
  const double idle[2] = {-1.0, 0.0};
  StepResult result;
  for (int k = 0; k < 50; ++k) {
    ASSERT_FALSE(result.terminated || result.truncated) << "step " << k;
    result = env.Step(idle, obs.data());
  }
  EXPECT_TRUE(result.truncated);
  EXPECT_FALSE(result.terminated);
  ASSERT_TRUE(result.episode.has_value());
  EXPECT_TRUE(result.episode->truncated);
  EXPECT_EQ(result.episode->steps, 50);
  EXPECT_NEAR(result.episode->cumulative_reward, -50.0, 1e-9);

  // The cumulative-reward floor terminates a training episode, not a test-mode one.
  config.max_steps = 2000;
  config.min_cumulative_reward = -20.0;
  config.test_mode = false;
  Environment training = MakeEnvironment(s, config);
  training.Reset(0, obs.data());
  int steps = 0;
  do {
    result = training.Step(idle, obs.data());
    ++steps;
  } while (!result.terminated && steps < 100);
  EXPECT_EQ(steps, 21);
  EXPECT_FALSE(result.truncated);
}

TEST(Environment, MeanCrossTrackErrorExcludesResetObservation) {
  Scenario s = StraightScenario(1000.0);
  s.vessel_position = {10.0, 20.0};
  EnvironmentConfig config;
  config.max_steps = 3;
  Environment env = MakeEnvironment(s, config);
  std::vector<float> obs(kObservationSize);
  env.Reset(0, obs.data());
  const double idle[2] = {-1.0, 0.0};
  StepResult result;
  for (int k = 0; k < 3; ++k) result = env.Step(idle, obs.data());
  ASSERT_TRUE(result.episode.has_value());
  EXPECT_NEAR(result.episode->mean_abs_cte, 20.0, 1e-9);
  EXPECT_NEAR(result.episode->path_length, 1000.0, 1e-6);
}

std::vector<float> Rollout(std::uint64_t seed, int steps) {
  Environment env(EnvironmentConfig{}, std::make_shared<TrainingScenarioGenerator>());
  std::vector<float> obs(kObservationSize);
  std::vector<float> trajectory;
  env.Reset(seed, obs.data());
  for (int k = 0; k < steps; ++k) {
    const double action[2] = {1.0, std::sin(0.05 * k)};
    const StepResult result = env.Step(action, obs.data());
    trajectory.insert(trajectory.end(), obs.begin(), obs.end());
    if (result.terminated || result.truncated) break;
  }
  return trajectory;
}

TEST(Environment, SameSeedSameTrajectoryDifferentSeedDifferentWorld) {
  EXPECT_EQ(Rollout(42, 200), Rollout(42, 200));
  EXPECT_NE(Rollout(42, 50), Rollout(43, 50));
}

}  // namespace
}  // namespace colav

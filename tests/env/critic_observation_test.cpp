// The privileged critic's observation of the nearest vessels: body-frame values against
// hand-computed cases, the order and range rules, and the batched environment's rows.
#include "env/critic_observation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "env/angles.h"
#include "env/batched_environment.h"
#include "env/environment.h"
#include "env/scenario_file.h"
#include "env/world.h"

namespace colav {
namespace {

VesselObstacleSpec Vessel(double x, double y, double course, double speed, double width) {
  VesselObstacleSpec vessel;
  vessel.position = {x, y};
  vessel.course = course;
  vessel.speed = speed;
  vessel.width = width;
  return vessel;
}

// The agent at the origin with `heading` and surge 0.5 m/s, sway 0.1 m/s, on a straight path.
Scenario AgentAmong(std::vector<VesselObstacleSpec> vessels, double heading) {
  Scenario scenario;
  scenario.name = "critic";
  scenario.waypoints = {{0.0, 0.0}, {1000.0, 0.0}};
  scenario.vessel_heading = heading;
  scenario.vessel_velocity = {0.5, 0.1, 0.0};
  scenario.dynamic_obstacles = std::move(vessels);
  return scenario;
}

std::vector<float> CriticObservationOf(const Scenario& scenario, int vessels) {
  World world;
  world.Load(scenario);
  std::vector<float> out(CriticObservationSize(vessels), -9.0f);
  WriteCriticObservation(world, vessels, out.data());
  return out;
}

TEST(CriticObservation, BodyFrameValuesOfOneVessel) {
  // Heading 0: the body frame is the world frame. The obstacle moves along +y at 0.3 m/s; the
  // agent moves at (0.5, 0.1), so the relative velocity is (-0.5, 0.2).
  const std::vector<float> ahead =
      CriticObservationOf(AgentAmong({Vessel(30.0, 40.0, kPi / 2.0, 0.3, 8.0)}, 0.0), 1);
  const std::vector<float> expected = {1.0f,          0.2f,         40.0f / 150.0f,
                                       -0.5f / 0.57f, 0.2f / 0.57f, 0.8f};
  for (int i = 0; i < kCriticValuesPerVessel; ++i) EXPECT_NEAR(ahead[i], expected[i], 1e-6) << i;

  // Heading pi/2: a world vector (wx, wy) is (wy, -wx) in the body frame; the agent's world
  // velocity is (-0.1, 0.5), the relative one (0.1, -0.2), in the body frame (-0.2, -0.1).
  const std::vector<float> turned =
      CriticObservationOf(AgentAmong({Vessel(30.0, 40.0, kPi / 2.0, 0.3, 8.0)}, kPi / 2.0), 1);
  const std::vector<float> expected_turned = {1.0f,          40.0f / 150.0f, -0.2f,
                                              -0.2f / 0.57f, -0.1f / 0.57f,  0.8f};
  for (int i = 0; i < kCriticValuesPerVessel; ++i) {
    EXPECT_NEAR(turned[i], expected_turned[i], 1e-6) << i;
  }
}

TEST(CriticObservation, NearestFirstWithinRangeThenZeros) {
  const Scenario scenario = AgentAmong({Vessel(0.0, 200.0, 0.0, 0.2, 5.0),   // 200 m
                                        Vessel(400.0, 0.0, 0.0, 0.2, 5.0),   // out of range
                                        Vessel(-50.0, 0.0, 0.0, 0.2, 5.0)},  // 50 m
                                       0.0);
  const std::vector<float> out = CriticObservationOf(scenario, 3);
  EXPECT_FLOAT_EQ(out[0], 1.0f);
  EXPECT_NEAR(out[1], -50.0 / 150.0, 1e-6);  // the nearest first
  EXPECT_FLOAT_EQ(out[kCriticValuesPerVessel], 1.0f);
  EXPECT_NEAR(out[kCriticValuesPerVessel + 2], 200.0 / 150.0, 1e-6);
  for (int i = 2 * kCriticValuesPerVessel; i < 3 * kCriticValuesPerVessel; ++i) {
    EXPECT_EQ(out[i], 0.0f) << "the third slot: no third vessel within range";
  }
  // Fewer slots than vessels in range: the nearest only.
  const std::vector<float> one = CriticObservationOf(scenario, 1);
  EXPECT_NEAR(one[1], -50.0 / 150.0, 1e-6);
}

TEST(CriticObservation, BatchedRowsFollowResetsStepsAndEpisodeEnds) {
  const Scenario scenario = AgentAmong({Vessel(60.0, 10.0, kPi, 0.4, 6.0)}, 0.0);
  EnvironmentConfig config;
  config.max_steps = 3;  // the episode is truncated on the third step
  BatchedEnvironment envs(config, std::vector<Scenario>{scenario}, 1);
  envs.ObserveVesselsForCritic(2);
  ASSERT_EQ(envs.critic_observation_size(), 2 * kCriticValuesPerVessel);
  envs.Reset();

  // A twin world stepped alike gives the rows each step should hold.
  Environment twin(config, std::make_shared<FixedScenarioSource>(scenario));
  std::vector<float> observation(ObservationSize(config));
  twin.Reset(0, observation.data());
  std::vector<float> expected(envs.critic_observation_size());
  const auto expect_rows = [&](const float* rows, const char* what) {
    WriteCriticObservation(twin.world(), 2, expected.data());
    EXPECT_EQ(std::vector<float>(rows, rows + expected.size()), expected) << what;
  };
  expect_rows(envs.critic_observations(), "after the reset");
  const std::vector<float> reset_rows(envs.critic_observations(),
                                      envs.critic_observations() + expected.size());
  const float action[kActionSize] = {1.0f, 0.5f};
  const double twin_action[kActionSize] = {1.0, 0.5};
  for (int t = 1; t <= 3; ++t) {
    envs.Step(action);
    twin.Step(twin_action, observation.data());
    if (t < 3) expect_rows(envs.critic_observations(), "after a step");
  }
  ASSERT_TRUE(envs.truncated()[0]);
  expect_rows(envs.final_critic_observations(), "the finished episode's last state");
  EXPECT_EQ(
      std::vector<float>(envs.critic_observations(), envs.critic_observations() + expected.size()),
      reset_rows)
      << "the next episode's reset state";
  EXPECT_NE(reset_rows, expected) << "the vessel moved during the episode";
}

}  // namespace
}  // namespace colav

// The manoeuvre search against cases whose answer follows from the vessel's top speed (0.58 m/s,
// forward only): a wide vessel overtaking ours at 2 m/s from 25 m astern cannot be escaped, a
// small one closing at 0.3 m/s from 200 m astern can be outrun, and drifting lets it hit.
#include "eval/collision_avoidability.h"

#include <gtest/gtest.h>

#include "env/world.h"
#include "tests/eval/head_on_encounter.h"

namespace colav {
namespace {

// A vessel obstacle of `width` whose centre starts `behind` metres astern of ours (at the
// origin, heading +x), moving along +x at `speed`.
std::vector<MovingObstacle> Overtaking(double behind, double width, double speed) {
  VesselObstacleSpec spec;
  spec.position = Eigen::Vector2d(-behind, 0.0);
  spec.width = width;
  spec.course = 0.0;
  spec.speed = speed;
  return {MovingObstacle(spec)};
}

const VesselState kAtRest = VesselState::Zero();

TEST(CollisionAvoidabilityTest, TheCandidatesAreHeldActionsThenSwitchedPairs) {
  const std::vector<Manoeuvre> manoeuvres = CandidateManoeuvres();
  ASSERT_EQ(manoeuvres.size(), 15U + 5U * 15U * 14U);
  for (int k = 0; k < 15; ++k) EXPECT_EQ(manoeuvres[k].first, manoeuvres[k].second);
  EXPECT_EQ(manoeuvres[15].switch_after, 5);
  EXPECT_NE(manoeuvres[15].first, manoeuvres[15].second);
  EXPECT_EQ(manoeuvres.back().switch_after, 120);
}

TEST(CollisionAvoidabilityTest, AWideFastVesselCloseAsternCannotBeEscaped) {
  const AvoidanceSearch search({}, Overtaking(25.0, 40.0, 2.0));
  EXPECT_FALSE(search.FindClearManoeuvre(kAtRest, 60).has_value());
}

TEST(CollisionAvoidabilityTest, ASlowVesselFarAsternCanBeOutrunButHitsADriftingVessel) {
  const AvoidanceSearch search({}, Overtaking(200.0, 10.0, 0.3));
  const Manoeuvre drift{{-1.0, 0.0}, 1 << 30, {-1.0, 0.0}};
  EXPECT_FALSE(search.StaysClear(kAtRest, drift, 1000));
  const Manoeuvre full_ahead{{1.0, 0.0}, 1 << 30, {1.0, 0.0}};
  EXPECT_TRUE(search.StaysClear(kAtRest, full_ahead, 1000));
  const std::optional<Manoeuvre> found = search.FindClearManoeuvre(kAtRest, 1000);
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(search.StaysClear(kAtRest, *found, 1000));
}

TEST(CollisionAvoidabilityTest, StaticObstaclesCountAndTheHorizonBoundsTheSearch) {
  // A circle 30 m ahead: full speed ahead hits it after about a minute, not within 20 s.
  const AvoidanceSearch search({CircleSpec{Eigen::Vector2d(30.0, 0.0), 5.0}}, {});
  const Manoeuvre full_ahead{{1.0, 0.0}, 1 << 30, {1.0, 0.0}};
  EXPECT_TRUE(search.StaysClear(kAtRest, full_ahead, 20));
  EXPECT_FALSE(search.StaysClear(kAtRest, full_ahead, 300));
  EXPECT_TRUE(search.FindClearManoeuvre(kAtRest, 300).has_value());
}

// Whether the world, stepped on under `manoeuvre`, stays collision-free for `steps` steps.
bool WorldStaysClear(World& world, const Manoeuvre& manoeuvre, int steps) {
  for (int step = 0; step < steps; ++step) {
    const auto& action = step < manoeuvre.switch_after ? manoeuvre.first : manoeuvre.second;
    world.Advance(CybershipModel::ForceFromAction(action[0], action[1]));
    if (world.collision()) return false;
  }
  return true;
}

TEST(CollisionAvoidabilityTest, TheSearchAgreesWithTheWorldItStartsFrom) {
  // A vessel closing head-on at 1 m/s from 150 m; the world has drifted for 100 s.
  const Scenario scenario = testing_util::HeadOnEncounter(150.0, 1.0);
  constexpr int kDrift = 100;
  constexpr int kHorizon = 200;
  const Manoeuvre drift{{-1.0, 0.0}, 1 << 30, {-1.0, 0.0}};
  World world;
  world.Load(scenario);
  for (int step = 0; step < kDrift; ++step) {
    world.Advance(CybershipModel::ForceFromAction(-1.0, 0.0));
  }
  const AvoidanceSearch search(world.static_obstacles(), world.moving_obstacles());
  const std::optional<Manoeuvre> found = search.FindClearManoeuvre(world.vessel(), kHorizon);
  ASSERT_TRUE(found.has_value());
  ASSERT_FALSE(search.StaysClear(world.vessel(), drift, kHorizon));

  World drifting;
  drifting.Load(scenario);
  EXPECT_FALSE(WorldStaysClear(drifting, drift, kDrift + kHorizon));
  EXPECT_TRUE(WorldStaysClear(world, *found, kHorizon));
}

}  // namespace
}  // namespace colav

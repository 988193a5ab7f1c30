// The manoeuvre search against cases whose answer follows from the vessel's top speed (0.58 m/s,
// forward only): a wide vessel overtaking ours at 2 m/s from 10 m astern cannot be escaped, a
// small one closing at 0.3 m/s from 200 m astern can be outrun, and drifting lets it hit.
#include "eval/collision_avoidability.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace colav

// Could any manoeuvre have avoided a collision? The moving vessels of a scenario hold their course
// and speed whatever our vessel does (reference-simulator 5.2), so from our vessel's state at some
// step the question concerns our vessel's motion alone: every candidate manoeuvre is simulated
// with the vessel model against the obstacles' known future, as World::Advance steps them.
// Finding one that stays clear proves the collision avoidable from that step; finding none says
// that no manoeuvre of this family avoids it (a search, not a proof of the contrary).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "env/collision_checker.h"
#include "env/environment_spec.h"
#include "env/obstacles.h"
#include "env/vessel_model.h"

namespace colav {

/// A piecewise-constant action sequence: `first` for `switch_after` steps, then `second`.
struct Manoeuvre {
  std::array<double, kActionSize> first{};
  int switch_after = 0;
  std::array<double, kActionSize> second{};
};

/// The manoeuvres tried: each of 15 actions (thrust 0, 1 or 2 N; yaw moment -1, -1/2, 0, 1/2 or 1
/// times the maximum) held throughout, then each ordered pair of different ones switched after 5,
/// 15, 30, 60 or 120 s: 1,065 in all, the held ones first.
std::vector<Manoeuvre> CandidateManoeuvres();

/// The obstacles of one scenario as they are at the step a search starts from.
class AvoidanceSearch {
 public:
  AvoidanceSearch(std::vector<CircleSpec> circles, std::vector<MovingObstacle> vessels);

  /// Whether `manoeuvre`, started from `vessel`, keeps the vessel's disc off every obstacle for
  /// `steps` steps.
  bool StaysClear(const VesselState& vessel, const Manoeuvre& manoeuvre, int steps) const;

  /// The first of CandidateManoeuvres() that stays clear for `steps` steps, if any.
  std::optional<Manoeuvre> FindClearManoeuvre(const VesselState& vessel, int steps) const;

 private:
  std::vector<CircleSpec> circles_;
  std::vector<MovingObstacle> vessels_;
  mutable CollisionChecker checker_;  // Collides() keeps scratch state
};

}  // namespace colav

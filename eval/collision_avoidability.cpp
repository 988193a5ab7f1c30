#include "eval/collision_avoidability.h"

#include <utility>

#include "env/world.h"

namespace colav {
namespace {

// Thrust actions -1, 0, 1 give 0, 1 and 2 N (forward only); moment actions span the range.
constexpr std::array<double, 3> kThrustActions = {-1.0, 0.0, 1.0};
constexpr std::array<double, 5> kMomentActions = {-1.0, -0.5, 0.0, 0.5, 1.0};
// Seconds the first action of a two-part manoeuvre is held: from a short swerve to a long turn.
constexpr std::array<int, 5> kSwitchAfter = {5, 15, 30, 60, 120};
// Held actions never switch.
constexpr int kNeverSwitch = 1 << 30;

std::vector<std::array<double, kActionSize>> ActionGrid() {
  std::vector<std::array<double, kActionSize>> actions;
  for (const double thrust : kThrustActions) {
    for (const double moment : kMomentActions) actions.push_back({thrust, moment});
  }
  return actions;
}

}  // namespace

std::vector<Manoeuvre> CandidateManoeuvres() {
  const std::vector<std::array<double, kActionSize>> actions = ActionGrid();
  std::vector<Manoeuvre> manoeuvres;
  manoeuvres.reserve(actions.size() + kSwitchAfter.size() * actions.size() * (actions.size() - 1));
  for (const auto& action : actions) manoeuvres.push_back({action, kNeverSwitch, action});
  for (const int switch_after : kSwitchAfter) {
    for (const auto& first : actions) {
      for (const auto& second : actions) {
        if (first != second) manoeuvres.push_back({first, switch_after, second});
      }
    }
  }
  return manoeuvres;
}

AvoidanceSearch::AvoidanceSearch(std::vector<CircleSpec> circles,
                                 std::vector<MovingObstacle> vessels)
    : circles_(std::move(circles)),
      vessels_(std::move(vessels)),
      checker_(CybershipModel::kRadius) {
  checker_.Load(circles_, vessels_);
}

bool AvoidanceSearch::StaysClear(const VesselState& vessel, const Manoeuvre& manoeuvre,
                                 int steps) const {
  std::vector<MovingObstacle> vessels = vessels_;
  VesselState state = vessel;
  const GeneralisedForce first =
      CybershipModel::ForceFromAction(manoeuvre.first[0], manoeuvre.first[1]);
  const GeneralisedForce second =
      CybershipModel::ForceFromAction(manoeuvre.second[0], manoeuvre.second[1]);
  for (int step = 0; step < steps; ++step) {
    for (MovingObstacle& obstacle : vessels) obstacle.Advance(kTimeStep);
    state = CybershipModel::Step(state, step < manoeuvre.switch_after ? first : second, kTimeStep);
    if (checker_.Collides(state.head<2>(), vessels)) return false;
  }
  return true;
}

std::optional<Manoeuvre> AvoidanceSearch::FindClearManoeuvre(const VesselState& vessel,
                                                             int steps) const {
  static const std::vector<Manoeuvre> kCandidates = CandidateManoeuvres();
  for (const Manoeuvre& manoeuvre : kCandidates) {
    if (StaysClear(vessel, manoeuvre, steps)) return manoeuvre;
  }
  return std::nullopt;
}

}  // namespace colav

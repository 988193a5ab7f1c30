// When the next policy of an ensemble takes the helm, for the rest of an episode or until the
// vessel stalls again (eval/policy_ensemble.h). Our most cautious agents time out where they stop
// or circle before a passage (docs/results.md, "A relief when the vessel stalls"): another policy
// then steers. Kept apart from the ensemble, which needs LibTorch, so that study files can name a
// rule.
#pragma once

#include <cstddef>

namespace colav {

/// The pace average's value at an episode's start (m/s), about our agents' cruising speed (the
/// reward's top speed is 0.57 m/s), so that a vessel starting from rest is not taken for stalled.
inline constexpr double kStallPaceStartMps = 0.5;

/// The longest pace average a rule may name (steps): beyond any episode (2,000 steps).
inline constexpr int kMaxStallSteps = 100000;

/// The vessel stalls once its pace towards the look-ahead point, u cos(heading error) (m/s),
/// averaged exponentially over `steps` steps from kStallPaceStartMps at the episode's start,
/// falls below `pace_mps` (0 < pace_mps < kStallPaceStartMps, 1 <= steps <= kMaxStallSteps). A
/// vessel stopped or circling makes no pace; one swerving round an obstacle still does. Each stall
/// restarts the average from kStallPaceStartMps, so the next one is the relief's own.
struct StallRule {
  double pace_mps = 0.1;
  int steps = 200;
};

/// Whether an ensemble of `members` policies may take the range rule (near_within_m): that rule
/// shares the helm between two, so members beyond two can only be reliefs, which need a stall
/// rule.
inline bool RangeRuleFits(std::size_t members, bool has_stall_rule) {
  return members == 2 || has_stall_rule;
}

}  // namespace colav

// Where a probability of improvement in progress is decided. Most scenarios end at the goal for
// both models compared, and there the one whose last step lands farther along the path wins,
// by hundredths of a point (the goal test ends an episode within 5 m of the path's end or at 99 %
// of it). So P(A makes more progress than B) can stay below 0.5 for an A that fails far less
// often than B (README, "Two helmsmen"). This splits it: over the pairs (A's seed, B's seed,
// scenario) where both reached the goal, and over the others, each with ties counted half.
#pragma once

#include <vector>

#include "eval/study/study_results.h"

namespace colav {

struct ProgressAtGoalSplit {
  double both_at_goal_share = 0.0;        ///< of the pairs, in [0, 1]
  double both_at_goal_probability = 0.0;  ///< P(A's progress > B's) among them
  double elsewhere_probability = 0.0;     ///< ... among the pairs where either failed
};

/// A's and B's seed models, on the same scenarios.
ProgressAtGoalSplit SplitProgressAtGoal(const std::vector<const ModelEpisodes*>& a,
                                        const std::vector<const ModelEpisodes*>& b);

}  // namespace colav

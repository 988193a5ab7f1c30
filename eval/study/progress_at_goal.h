// Where a probability of improvement in progress is decided. Most scenarios end at the goal for
// both models compared, and there the one whose last step lands farther along the path wins.
// Where it lands is set by the line of approach, not by how far the vessel got: the goal test
// ends an episode within 5 m of the path's end or at 99 % of it, so a vessel that enters the 5 m
// circle d metres beside the path ends with its nearest path point sqrt(25 - d^2) metres before
// the end (5 m for one on the path), or at the 99 % line where that comes first (docs/results.md,
// "Where the progress comparison is decided"). So P(A makes more progress than B) can stay below
// 0.5 for an A that fails far less often than B. This splits it: over the pairs (A's seed, B's
// seed, scenario) where both reached the goal, and over the others, each with ties counted half;
// and it scores progress to the finish, where every goal counts 100 %.
#pragma once

#include <vector>

#include "eval/study/study_results.h"
#include "src/seed_aggregates.h"

namespace colav {

struct ProgressAtGoalSplit {
  double both_at_goal_share = 0.0;        ///< of the pairs, in [0, 1]
  double both_at_goal_probability = 0.0;  ///< P(A's progress > B's) among them
  double elsewhere_probability = 0.0;     ///< ... among the pairs where either failed
};

/// A's and B's seed models, on the same scenarios.
ProgressAtGoalSplit SplitProgressAtGoal(const std::vector<const ModelEpisodes*>& a,
                                        const std::vector<const ModelEpisodes*>& b);

/// The key of progress to the finish among a comparison's metrics (summary.json).
inline constexpr char kProgressToFinish[] = "progress_to_finish";

/// Progress to the finish, [seed][scenario] in %: 100 for an episode that reached the goal, its
/// progress otherwise. Every finish ties, so a comparison on it is decided by the episodes that
/// end short of the goal.
SeedScores ProgressToFinish(const std::vector<const ModelEpisodes*>& seeds);

}  // namespace colav

// Where a model's progress and cross-track error go: its episodes split by how they ended (a
// collision, a time-out, or the rest, which end at the goal), each part's share of the episodes,
// of the mean progress lost and of the mean cross-track error. The parts add up to the model's
// totals (progress lost = 100 - mean progress). Even an agent that never collides or times out
// loses about a point: the goal test ends an episode within 5 m of the path's end or at 99 % of it.
#pragma once

#include <vector>

#include "eval/study/study_results.h"

namespace colav {

struct OutcomePart {
  double share = 0.0;              ///< % of the episodes
  double progress_lost = 0.0;      ///< points of the mean progress lost in these episodes
  double cross_track_error = 0.0;  ///< m of the mean cross-track error from these episodes
};

struct OutcomeBreakdown {
  OutcomePart collision, time_out, rest;
  int time_out_scenarios = 0;   ///< scenarios in which some seed timed out
  int time_out_every_seed = 0;  ///< ... in which every seed did
};

/// Over every episode of every seed (the models' episodes of one scenario set, paired).
OutcomeBreakdown BreakDownOutcomes(const std::vector<const ModelEpisodes*>& seeds);

}  // namespace colav

// Where a single agent (one trained policy, such as each of the authors') falls among the training
// seeds of one of our configurations. A single agent is one draw of its own recipe's seeds: its
// interval over the scenarios bounds what that one policy scores, not where another seed of its
// recipe would land, and the configuration's interval over seeds bounds the configuration's
// mean, not one seed. Asking whether a mean over our seeds falls inside the agent's interval mixes
// the two. The question asked here is the other way round: could the agent have been one more
// seed of the configuration? Per metric: the 95 % prediction interval for one more seed's mean
// (src/statistics.h; it assumes the seeds' means spread normally), whether the agent lies
// inside, how many of the seeds did better than it, and a rank test that assumes nothing about
// the spread: were the agent one more seed, its rank among the n + 1 would be uniform.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "eval/study/study_results.h"
#include "src/rate_interval.h"

namespace colav {

struct SeedPlacement {
  double value = 0.0;    ///< the agent's mean over the scenarios
  Interval prediction;   ///< for one more seed's mean; for bounded metrics clipped to [0, scale]
  bool inside = false;   ///< value within `prediction`
  int seeds_better = 0;  ///< seeds whose mean is strictly better than the agent's
  int seeds_worse = 0;   ///< seeds whose mean is strictly worse than the agent's
  int seeds = 0;
  /// Two-sided rank test of "the agent is one more seed": twice the chance that one more seed
  /// ranks at least as far out on the agent's side among the n + 1, ties counted against the
  /// test, at most 1. Its least value is 2 / (n + 1): below 0.05 needs 39 seeds or more.
  double rank_p = 1.0;
};

struct AgentAmongSeeds {
  std::string config;
  std::string agent;
  std::map<std::string, SeedPlacement> metrics;  ///< by StudyMetric::name, every StudyMetrics()
};

/// `seeds`: the configuration's seed models (at least two, std::invalid_argument otherwise);
/// `agent`: the single agent's episodes of the same scenarios.
AgentAmongSeeds PlaceAmongSeeds(const std::string& config,
                                const std::vector<const ModelEpisodes*>& seeds,
                                const std::string& agent_name, const ModelEpisodes& agent);

}  // namespace colav

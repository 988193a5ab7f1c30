// Where a single agent (one trained policy, such as each of the authors') falls among the training
// seeds of one of our configurations. A single agent is one draw of its own recipe's seeds: its
// interval over the scenarios bounds what that one policy scores, not where another seed of its
// recipe would land, and the configuration's interval over seeds bounds the configuration's
// mean, not one seed. Asking whether a mean over our seeds falls inside the agent's interval mixes
// the two. The question asked here is the other way round: could the agent have been one more
// seed of the configuration? Per metric: the 95 % prediction interval for one more seed's mean
// (src/statistics.h; it assumes the seeds' means spread normally), whether the agent lies
// inside, and how many of the seeds did better than it.
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
  int seeds = 0;
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

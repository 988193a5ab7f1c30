#include "eval/study/agent_among_seeds.h"

#include <algorithm>

#include "src/statistics.h"

namespace colav {
namespace {

// Were the agent one more of our n = `seeds` seeds, its rank among the n + 1 would be uniform: the
// chance that at most `better` of ours beat it is (better + 1) / (n + 1). Ties count on both
// sides, which makes the test conservative.
double RankP(int better, int worse, int seeds) {
  const int ties = seeds - better - worse;
  const int nearest_side = std::min(better, worse) + ties + 1;
  return std::min(1.0, 2.0 * nearest_side / (seeds + 1));
}

}  // namespace

AgentAmongSeeds PlaceAmongSeeds(const std::string& config,
                                const std::vector<const ModelEpisodes*>& seeds,
                                const std::string& agent_name, const ModelEpisodes& agent) {
  AgentAmongSeeds placement{config, agent_name, {}};
  for (const StudyMetric& metric : StudyMetrics()) {
    std::vector<double> seed_means;
    seed_means.reserve(seeds.size());
    for (const ModelEpisodes* seed : seeds) seed_means.push_back(Mean(seed->at(metric.name)));
    SeedPlacement& place = placement.metrics[metric.name];
    place.value = Mean(agent.at(metric.name));
    place.prediction = PredictionInterval(seed_means);
    if (metric.bounded()) {
      place.prediction.low = std::max(place.prediction.low, 0.0);
      place.prediction.high = std::min(place.prediction.high, metric.scale);
    }
    place.inside = place.prediction.low <= place.value && place.value <= place.prediction.high;
    place.seeds = static_cast<int>(seed_means.size());
    const auto higher = static_cast<int>(std::count_if(
        seed_means.begin(), seed_means.end(), [&](double mean) { return mean > place.value; }));
    const auto lower = static_cast<int>(std::count_if(
        seed_means.begin(), seed_means.end(), [&](double mean) { return mean < place.value; }));
    place.seeds_better = metric.higher_is_better ? higher : lower;
    place.seeds_worse = metric.higher_is_better ? lower : higher;
    place.rank_p = RankP(place.seeds_better, place.seeds_worse, place.seeds);
  }
  return placement;
}

}  // namespace colav

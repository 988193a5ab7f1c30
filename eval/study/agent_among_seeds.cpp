#include "eval/study/agent_among_seeds.h"

#include <algorithm>

#include "src/statistics.h"

namespace colav {

AgentAmongSeeds PlaceAmongSeeds(const std::string& config,
                                const std::vector<const ModelEpisodes*>& seeds,
                                const std::string& agent_name, const ModelEpisodes& agent) {
  AgentAmongSeeds placement{config, agent_name, {}};
  for (const StudyMetric& metric : StudyMetrics()) {
    std::vector<double> seed_means;
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
    place.seeds_better =
        static_cast<int>(std::count_if(seed_means.begin(), seed_means.end(), [&](double seed_mean) {
          return metric.higher_is_better ? seed_mean > place.value : seed_mean < place.value;
        }));
  }
  return placement;
}

}  // namespace colav

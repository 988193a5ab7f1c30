#include "eval/study/outcome_breakdown.h"

#include <cstddef>

namespace colav {

OutcomeBreakdown BreakDownOutcomes(const std::vector<const ModelEpisodes*>& seeds) {
  OutcomeBreakdown breakdown;
  if (seeds.empty()) return breakdown;
  const std::size_t scenarios = seeds.front()->at("progress").size();
  const double episodes = static_cast<double>(scenarios * seeds.size());
  std::vector<int> time_outs(scenarios, 0);
  for (const ModelEpisodes* seed : seeds) {
    // Progress and the 0/1 outcomes are in % (study_results.h).
    const std::vector<double>& progress = seed->at("progress");
    const std::vector<double>& cte = seed->at("cross_track_error");
    const std::vector<double>& collision = seed->at("collision");
    const std::vector<double>& time_out = seed->at("time_out");
    for (std::size_t i = 0; i < scenarios; ++i) {
      OutcomePart& part = collision[i] > 0.0  ? breakdown.collision
                          : time_out[i] > 0.0 ? breakdown.time_out
                                              : breakdown.rest;
      part.share += 100.0 / episodes;
      part.progress_lost += (100.0 - progress[i]) / episodes;
      part.cross_track_error += cte[i] / episodes;
      if (&part == &breakdown.time_out) ++time_outs[i];
    }
  }
  for (const int count : time_outs) {
    breakdown.time_out_scenarios += count > 0 ? 1 : 0;
    breakdown.time_out_every_seed += count == static_cast<int>(seeds.size()) ? 1 : 0;
  }
  return breakdown;
}

}  // namespace colav

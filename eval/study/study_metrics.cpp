#include "eval/study/study_metrics.h"

#include <algorithm>

namespace colav {

const std::vector<StudyMetric>& StudyMetrics() {
  static const std::vector<StudyMetric> kMetrics = {
      {"progress", "progress", "progress %", 100.0, true, false},
      {"cross_track_error", "mean_cte", "cte m", 1.0, false, false},
      {"duration", "steps", "duration", 1.0, false, false},
      {"collision", "collision", "collisions %", 100.0, false, true},
      {"goal", "goal", "goal %", 100.0, true, true},
      // episodes that ran out of steps without a collision or the goal: evaluate's `truncated`
      {"time_out", "truncated", "time-outs %", 100.0, false, true},
      // the episode's summed reward: the objective the learner maximises, every term in one number
      {"return", "reward", "return", 1.0, true, false},
  };
  return kMetrics;
}

const StudyMetric* FindStudyMetric(const std::string& name) {
  const auto& metrics = StudyMetrics();
  const auto metric = std::find_if(metrics.begin(), metrics.end(),
                                   [&](const StudyMetric& m) { return m.name == name; });
  return metric == metrics.end() ? nullptr : &*metric;
}

}  // namespace colav

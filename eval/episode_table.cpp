#include "eval/episode_table.h"

#include <sstream>

namespace colav {

std::string EpisodeTableHeader() {
  return "model,scenario,seed,progress,mean_cte,steps,collision,goal,truncated,reward,path_length";
}

std::string EpisodeTable(const std::vector<std::string>& model_names,
                         const std::vector<EvaluationEpisode>& episodes,
                         const std::vector<std::vector<EpisodeOutcome>>& outcomes) {
  std::ostringstream table;
  table.precision(17);
  table << EpisodeTableHeader() << '\n';
  for (std::size_t m = 0; m < model_names.size(); ++m) {
    for (std::size_t e = 0; e < episodes.size(); ++e) {
      const EpisodeMetrics& metrics = outcomes[m][e].metrics;
      table << model_names[m] << ',' << episodes[e].name << ',';
      if (episodes[e].seed) table << *episodes[e].seed;
      table << ',' << metrics.progress << ',' << metrics.mean_abs_cte << ',' << metrics.steps << ','
            << metrics.collision << ',' << metrics.goal_reached << ',' << metrics.truncated << ','
            << metrics.cumulative_reward << ',' << metrics.path_length << '\n';
    }
  }
  return table.str();
}

}  // namespace colav

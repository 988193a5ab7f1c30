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

EpisodeMetrics EpisodeMetricsOfRow(const std::vector<std::string>& row) {
  EpisodeMetrics metrics;
  metrics.progress = std::stod(row.at(3));
  metrics.mean_abs_cte = std::stod(row.at(4));
  metrics.steps = std::stoll(row.at(5));
  metrics.collision = row.at(6) == "1";
  metrics.goal_reached = row.at(7) == "1";
  metrics.truncated = row.at(8) == "1";
  metrics.cumulative_reward = std::stod(row.at(9));
  metrics.path_length = std::stod(row.at(10));
  return metrics;
}

}  // namespace colav

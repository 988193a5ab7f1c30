// episodes.csv of an evaluation: one row per episode and model.
#pragma once

#include <string>
#include <vector>

#include "eval/episode_runner.h"
#include "eval/evaluation_episodes.h"

namespace colav {

/// Header (no newline): model,scenario,seed,progress,mean_cte,steps,collision,goal,truncated,
/// reward,path_length. The seed is empty for scenario files; flags are 0/1; progress is the
/// fraction s*/L; values are printed with enough digits to be read back exactly.
std::string EpisodeTableHeader();

/// The table of outcomes[m][e] (policy m on episode e), models in order, episodes in order.
std::string EpisodeTable(const std::vector<std::string>& model_names,
                         const std::vector<EvaluationEpisode>& episodes,
                         const std::vector<std::vector<EpisodeOutcome>>& outcomes);

/// One row of that table (its cells, the header's columns) read back as the metrics it was
/// written from: exact, since the table keeps every value at full precision. std::invalid_argument
/// or std::out_of_range for a cell that is not a number, or a short row.
EpisodeMetrics EpisodeMetricsOfRow(const std::vector<std::string>& row);

}  // namespace colav

// The per-episode results of a study's evaluations, arranged for statistics: for each scenario
// set ("study": the study's scenarios, "paper": the paper's 100, "validation": scenarios to choose
// on) and each model, one row per scenario in the same order for every model (paired).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "eval/study/job_graph.h"
#include "eval/study/study_metrics.h"

namespace colav {

/// values[metric name][scenario] of one model.
using ModelEpisodes = std::map<std::string, std::vector<double>>;

struct ScenarioSetResults {
  int episodes = 0;
  std::uint64_t seed = 0;                       ///< the scenarios' master seed
  std::map<std::string, ModelEpisodes> models;  ///< by model name ("baseline.seed_0", "ref.x")
};

/// Reads eval/<group>/episodes.csv of every evaluation group; a missing or malformed file, or
/// groups of one scenario set with other scenarios, is a UserError naming the file.
std::map<std::string, ScenarioSetResults> ReadStudyResults(const StudySpec& spec,
                                                           const std::filesystem::path& out);

}  // namespace colav

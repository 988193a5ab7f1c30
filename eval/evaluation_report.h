// summary.json and summary.md of an evaluation: the per-model table in the form of the paper's DRL
// table and the paired differences between models, and reading summary.json back (beta sweep).
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "eval/evaluation_summary.h"

namespace colav {

struct EvaluationReport {
  std::string scenarios;              ///< "test" (generated) or "files"
  std::optional<std::uint64_t> seed;  ///< master seed of the test scenarios
  std::vector<ModelSummary> models;
  std::vector<PairedDifference> differences;  ///< every pair of models, in model order
  /// ProgramBuildId of the evaluate that ran it (src/build_id.h); empty when not told.
  std::string evaluator_build_id{};
};

/// The report of per-model episode metrics episodes[m] (all models on the same episodes): the
/// summaries and the differences of every pair (m1 < m2).
EvaluationReport MakeEvaluationReport(const std::string& scenarios,
                                      std::optional<std::uint64_t> seed,
                                      const std::vector<std::string>& names,
                                      const std::vector<std::string>& policies,
                                      const std::vector<std::vector<EpisodeMetrics>>& episodes);

/// summary.json: {"scenarios", "seed", "evaluator_build_id", "models": [{"name", "policy",
/// "policy_fingerprint", "observation_settings", "episodes", "goals_reached", "collisions",
/// "truncated", "metrics": {key: {"n", "mean", "sd", "low", "high", "half_width", "in_range":
/// {"method", "low", "high"}}}}], "paired_differences": [{"first", "second", "metrics":
/// {...}}]}. low/high are Student-t; in_range is the interval that
/// stays in the metric's range. Fractions (progress, collision, goal) stay fractions.
nlohmann::ordered_json EvaluationReportJson(const EvaluationReport& report);

/// summary.md: the paper-style table (metrics as rows, "mean [95 % CI]" per model with the
/// in-range intervals; progress and rates in %), the same with Student-t intervals, then the
/// paired differences (first minus second; bold where the interval
/// excludes 0).
std::string EvaluationReportMarkdown(const EvaluationReport& report);

/// The model summaries of a summary.json; UserError naming the file on a missing or malformed
/// file.
std::vector<ModelSummary> ReadModelSummaries(const std::filesystem::path& path);

}  // namespace colav

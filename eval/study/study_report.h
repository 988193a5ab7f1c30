// The study's report: each model's metrics with intervals (over training seeds for our PPO
// configurations, over scenarios for single agents), the probability that one configuration beats
// another on a random scenario and seed, where each model's progress and cross-track error go
// (outcome_breakdown.h), where each single agent falls among a configuration's seeds
// (agent_among_seeds.h), how far each model falls short of the study's goal and which model the
// validation scenarios choose by it (goal_shortfall.h), and the paper's table beside ours.
// Written as OUT/REPORT.md and OUT/summary.json (every figure of the report, machine-readable).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "eval/study/agent_among_seeds.h"
#include "eval/study/ensemble_gain.h"
#include "eval/study/outcome_breakdown.h"
#include "eval/study/progress_at_goal.h"
#include "eval/study/study_results.h"
#include "src/seed_aggregates.h"

namespace colav {

struct MetricEstimate {
  double mean = 0.0;
  Interval ci;
  std::string method;  ///< "t over seeds", "Wilson", "bootstrap", "t"
  double iqm = 0.0;    ///< interquartile mean of every episode of every seed
};

struct ModelSummary {
  std::string name;  ///< configuration name, or the single model's name
  int seeds = 1;
  std::map<std::string, MetricEstimate> metrics;
  OutcomeBreakdown outcomes;
};

struct ImprovementSummary {
  std::string model;
  std::string over;
  std::map<std::string, ImprovementEstimate> metrics;
  ProgressAtGoalSplit progress_split;  ///< where the progress comparison is decided
};

struct ScenarioSetReport {
  int episodes = 0;
  std::vector<ModelSummary> models;
  std::vector<ImprovementSummary> improvements;
  std::vector<AgentAmongSeeds> agents_among_seeds;  ///< every configuration x single agent
  std::vector<EnsembleGain> ensemble_gains;         ///< every ensemble kind, against its members
};

/// The report of one scenario set: configurations (models "<config>.seed_<k>") summarised over
/// their seeds, other models over scenarios; the probability of improvement of every
/// configuration over its own compare_to or else `reference_config` (if present) and over each
/// single model; where each single model falls among the seeds of each configuration of two or
/// more seeds; what each ensemble kind gains over its own members.
ScenarioSetReport SummariseScenarioSet(const StudySpec& spec, const ScenarioSetResults& results,
                                       const std::string& reference_config);

/// The summary of `model`, which `report` must hold.
const ModelSummary& SummaryOf(const ScenarioSetReport& report, const std::string& model);

/// How an ensemble kind's members share the helm, as the report says it after their list ("" when
/// they act with the mean of their actions).
std::string DescribeEnsembleRule(const EnsembleSpec& ensemble);

/// Writes OUT/summary.json and OUT/REPORT.md from the evaluations in OUT/eval/.
void WriteStudyReport(const StudySpec& spec, const std::filesystem::path& out, double wall_s);

}  // namespace colav

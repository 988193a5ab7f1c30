// The statistics of an evaluation: per model, the mean and Student-t 95 % interval of each
// episode metric (the paper's DRL table, reference-learning 7.2); between two models evaluated on
// the same episodes, the mean paired difference and its t-interval.
#pragma once

#include <string>
#include <vector>

#include "env/environment_spec.h"
#include "src/statistics.h"

namespace colav {

/// An episode metric the summary reports.
struct SummaryMetric {
  std::string key;    ///< JSON key: progress, cross_track_error, duration, collision, reward, goal
  std::string label;  ///< table label
  bool is_fraction;   ///< a rate or fraction, shown in % in tables
  double (*value)(const EpisodeMetrics&);
};

/// The reported metrics, in table order.
const std::vector<SummaryMetric>& SummaryMetrics();

/// The summary of one metric, in the metric's own unit (fractions stay fractions).
struct MetricSummary {
  std::string key;
  MeanConfidenceInterval interval;
};

struct ModelSummary {
  std::string name;
  std::string policy;  ///< the policy file
  int episodes = 0;
  int goals_reached = 0;
  int collisions = 0;
  int truncated = 0;
  std::vector<MetricSummary> metrics;  ///< SummaryMetrics() order
};

/// Model a minus model b on the same episodes.
struct PairedDifference {
  std::string first;
  std::string second;
  std::vector<MetricSummary> metrics;  ///< SummaryMetrics() order
};

/// The summary of a model's episodes (not empty).
ModelSummary SummariseModel(const std::string& name, const std::string& policy,
                            const std::vector<EpisodeMetrics>& episodes);

/// Metric by metric, the summary of first[k] - second[k] over the episodes k (same episodes,
/// same order, not empty; std::invalid_argument otherwise).
PairedDifference CompareModels(const std::string& first_name,
                               const std::vector<EpisodeMetrics>& first,
                               const std::string& second_name,
                               const std::vector<EpisodeMetrics>& second);

/// The MetricSummary of `key` in `metrics`; std::invalid_argument when absent.
const MetricSummary& FindMetric(const std::vector<MetricSummary>& metrics, const std::string& key);

}  // namespace colav

// The statistics of an evaluation: per model, the mean of each episode metric with two 95 %
// intervals, the paper's Student-t interval (reference-learning 7.2) and one that stays in the
// metric's range (Wilson score for rates, percentile bootstrap for progress, src/rate_interval.h);
// between two models evaluated on the same episodes, the mean paired difference and its
// t-interval.
#pragma once

#include <string>
#include <vector>

#include "env/environment_spec.h"
#include "src/rate_interval.h"
#include "src/statistics.h"

namespace colav {

/// How a metric's in-range interval is computed.
enum class RangeIntervalMethod {
  kStudentT,   ///< unbounded in practice (cross-track error, duration, reward)
  kWilson,     ///< a rate of 0/1 outcomes (collisions, goals reached)
  kBootstrap,  ///< a mean bounded to [0, 1] (progress)
};

/// "student_t", "wilson" or "bootstrap".
std::string RangeIntervalMethodName(RangeIntervalMethod method);

/// An episode metric the summary reports.
struct SummaryMetric {
  std::string key;    ///< JSON key: progress, cross_track_error, duration, collision, reward, goal
  std::string label;  ///< table label
  bool is_fraction;   ///< a rate or fraction, shown in % in tables
  RangeIntervalMethod range_method;
  double (*value)(const EpisodeMetrics&);
};

/// The reported metrics, in table order.
const std::vector<SummaryMetric>& SummaryMetrics();

/// The summary of one metric, in the metric's own unit (fractions stay fractions).
struct MetricSummary {
  std::string key;
  MeanConfidenceInterval interval;  ///< Student-t (the paper's)
  Interval in_range;                ///< by the metric's range_method; Student-t for differences
};

struct ModelSummary {
  std::string name;
  std::string policy;  ///< the policy file
  int episodes = 0;
  int goals_reached = 0;
  int collisions = 0;
  int truncated = 0;
  std::vector<MetricSummary> metrics;  ///< SummaryMetrics() order
  /// The observation settings the model ran under and where they came from, e.g. "closeness log
  /// (recorded in the file)"; empty when not told.
  std::string observation_settings;
  /// PolicyFingerprint of its policy file (eval/policy_fingerprint.h); empty when not told.
  std::string policy_fingerprint;
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

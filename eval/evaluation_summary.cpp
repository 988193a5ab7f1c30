#include "eval/evaluation_summary.h"

#include <stdexcept>

namespace colav {
namespace {

// The bootstrap's generator seed: fixed, so the same episodes give the same summary bytes.
constexpr std::uint64_t kBootstrapSeed = 20211206;

std::vector<double> MetricValues(const SummaryMetric& metric,
                                 const std::vector<EpisodeMetrics>& episodes) {
  std::vector<double> values;
  values.reserve(episodes.size());
  for (const EpisodeMetrics& episode : episodes) values.push_back(metric.value(episode));
  return values;
}

MetricSummary SummariseMetric(const SummaryMetric& metric, const std::vector<double>& values) {
  const MeanConfidenceInterval t = Summarise(values);
  switch (metric.range_method) {
    case RangeIntervalMethod::kWilson: {
      std::int64_t successes = 0;
      for (const double value : values) successes += value > 0.5 ? 1 : 0;
      return {metric.key, t, WilsonInterval(successes, static_cast<std::int64_t>(values.size()))};
    }
    case RangeIntervalMethod::kBootstrap:
      return {metric.key, t, PercentileBootstrapMean(values, kBootstrapSeed)};
    case RangeIntervalMethod::kStudentT:
      break;
  }
  return {metric.key, t, {t.low, t.high}};
}

}  // namespace

std::string RangeIntervalMethodName(RangeIntervalMethod method) {
  switch (method) {
    case RangeIntervalMethod::kWilson:
      return "wilson";
    case RangeIntervalMethod::kBootstrap:
      return "bootstrap";
    case RangeIntervalMethod::kStudentT:
      break;
  }
  return "student_t";
}

const std::vector<SummaryMetric>& SummaryMetrics() {
  static const std::vector<SummaryMetric> metrics = {
      {"progress", "progress", true, RangeIntervalMethod::kBootstrap,
       [](const EpisodeMetrics& e) { return e.progress; }},
      {"cross_track_error", "cross-track error (m)", false, RangeIntervalMethod::kStudentT,
       [](const EpisodeMetrics& e) { return e.mean_abs_cte; }},
      {"duration", "duration (steps)", false, RangeIntervalMethod::kStudentT,
       [](const EpisodeMetrics& e) { return static_cast<double>(e.steps); }},
      {"collision", "collisions", true, RangeIntervalMethod::kWilson,
       [](const EpisodeMetrics& e) { return e.collision ? 1.0 : 0.0; }},
      {"reward", "reward", false, RangeIntervalMethod::kStudentT,
       [](const EpisodeMetrics& e) { return e.cumulative_reward; }},
      {"goal", "goals reached", true, RangeIntervalMethod::kWilson,
       [](const EpisodeMetrics& e) { return e.goal_reached ? 1.0 : 0.0; }},
  };
  return metrics;
}

ModelSummary SummariseModel(const std::string& name, const std::string& policy,
                            const std::vector<EpisodeMetrics>& episodes) {
  ModelSummary summary{name, policy, static_cast<int>(episodes.size()), 0, 0, 0, {}, {}, {}};
  for (const EpisodeMetrics& episode : episodes) {
    summary.goals_reached += episode.goal_reached ? 1 : 0;
    summary.collisions += episode.collision ? 1 : 0;
    summary.truncated += episode.truncated ? 1 : 0;
  }
  for (const SummaryMetric& metric : SummaryMetrics()) {
    summary.metrics.push_back(SummariseMetric(metric, MetricValues(metric, episodes)));
  }
  return summary;
}

PairedDifference CompareModels(const std::string& first_name,
                               const std::vector<EpisodeMetrics>& first,
                               const std::string& second_name,
                               const std::vector<EpisodeMetrics>& second) {
  if (first.size() != second.size()) {
    throw std::invalid_argument("CompareModels: the models ran different numbers of episodes");
  }
  PairedDifference difference{first_name, second_name, {}};
  for (const SummaryMetric& metric : SummaryMetrics()) {
    const std::vector<double> a = MetricValues(metric, first);
    const std::vector<double> b = MetricValues(metric, second);
    std::vector<double> differences(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) differences[k] = a[k] - b[k];
    const MeanConfidenceInterval t = Summarise(differences);
    difference.metrics.push_back({metric.key, t, {t.low, t.high}});
  }
  return difference;
}

const MetricSummary& FindMetric(const std::vector<MetricSummary>& metrics, const std::string& key) {
  for (const MetricSummary& metric : metrics) {
    if (metric.key == key) return metric;
  }
  throw std::invalid_argument("no metric '" + key + "'");
}

}  // namespace colav

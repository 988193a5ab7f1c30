#include "eval/evaluation_report.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "src/error.h"

namespace colav {
namespace {

nlohmann::ordered_json MetricsJson(const std::vector<MetricSummary>& metrics) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const MetricSummary& metric : metrics) {
    json[metric.key] = ConfidenceIntervalJson(metric.interval);
  }
  return json;
}

// The model's metrics with, beside the Student-t fields, "in_range": {method, low, high}.
nlohmann::ordered_json ModelMetricsJson(const std::vector<MetricSummary>& metrics) {
  nlohmann::ordered_json json = MetricsJson(metrics);
  for (std::size_t k = 0; k < metrics.size(); ++k) {
    json[metrics[k].key]["in_range"] = {
        {"method", RangeIntervalMethodName(SummaryMetrics()[k].range_method)},
        {"low", metrics[k].in_range.low},
        {"high", metrics[k].in_range.high}};
  }
  return json;
}

nlohmann::ordered_json ModelJson(const ModelSummary& model) {
  return {{"name", model.name},
          {"policy", model.policy},
          {"policy_fingerprint", model.policy_fingerprint},
          {"observation_settings", model.observation_settings},
          {"episodes", model.episodes},
          {"goals_reached", model.goals_reached},
          {"collisions", model.collisions},
          {"truncated", model.truncated},
          {"metrics", ModelMetricsJson(model.metrics)}};
}

// "96.7 % [94.5, 98.9]" for fractions, "18.7 [16.6, 20.9]" otherwise; `sign` prefixes + to
// positive means (differences).
std::string FormatInterval(double mean, const Interval& interval, bool is_fraction, bool sign) {
  const double scale = is_fraction ? 100.0 : 1.0;
  char text[96];
  std::snprintf(text, sizeof text, sign ? "%+.1f%s [%.1f, %.1f]" : "%.1f%s [%.1f, %.1f]",
                mean * scale, is_fraction ? (sign ? " pp" : " %") : "", interval.low * scale,
                interval.high * scale);
  return text;
}

std::string FormatInterval(const MeanConfidenceInterval& interval, bool is_fraction, bool sign) {
  return FormatInterval(interval.mean, {interval.low, interval.high}, is_fraction, sign);
}

// Which of a metric's two intervals a table shows.
enum class TableInterval { kInRange, kStudentT };

std::string SummaryTable(const std::vector<ModelSummary>& models, TableInterval shown) {
  std::ostringstream table;
  table << "| metric |";
  for (const ModelSummary& model : models) table << ' ' << model.name << " |";
  table << "\n|---|";
  for (std::size_t m = 0; m < models.size(); ++m) table << "---|";
  table << '\n';
  for (std::size_t k = 0; k < SummaryMetrics().size(); ++k) {
    const SummaryMetric& metric = SummaryMetrics()[k];
    table << "| " << metric.label << " |";
    for (const ModelSummary& model : models) {
      const MetricSummary& summary = model.metrics[k];
      table << ' '
            << (shown == TableInterval::kInRange
                    ? FormatInterval(summary.interval.mean, summary.in_range, metric.is_fraction,
                                     false)
                    : FormatInterval(summary.interval, metric.is_fraction, false));
      if (metric.key == "goal") {
        table << " (" << model.goals_reached << '/' << model.episodes << ')';
      }
      table << " |";
    }
    table << '\n';
  }
  table << "| truncated episodes |";
  for (const ModelSummary& model : models) table << ' ' << model.truncated << " |";
  table << '\n';
  if (shown == TableInterval::kInRange) {
    table << "| observation settings |";
    for (const ModelSummary& model : models) {
      table << ' ' << (model.observation_settings.empty() ? "-" : model.observation_settings)
            << " |";
    }
    table << '\n';
  }
  return table.str();
}

std::string DifferenceTable(const std::vector<PairedDifference>& differences) {
  std::ostringstream table;
  table << "| first - second |";
  for (const SummaryMetric& metric : SummaryMetrics()) table << ' ' << metric.label << " |";
  table << "\n|---|";
  for (std::size_t k = 0; k < SummaryMetrics().size(); ++k) table << "---|";
  table << '\n';
  for (const PairedDifference& difference : differences) {
    table << "| " << difference.first << " - " << difference.second << " |";
    for (std::size_t k = 0; k < SummaryMetrics().size(); ++k) {
      const MeanConfidenceInterval& interval = difference.metrics[k].interval;
      const std::string cell = FormatInterval(interval, SummaryMetrics()[k].is_fraction, true);
      const bool excludes_zero = interval.low > 0.0 || interval.high < 0.0;
      table << ' ' << (excludes_zero ? "**" + cell + "**" : cell) << " |";
    }
    table << '\n';
  }
  return table.str();
}

ModelSummary ModelFromJson(const nlohmann::json& json) {
  ModelSummary model;
  model.name = json.at("name").get<std::string>();
  model.policy = json.at("policy").get<std::string>();
  model.episodes = json.at("episodes").get<int>();
  model.goals_reached = json.at("goals_reached").get<int>();
  model.collisions = json.at("collisions").get<int>();
  model.truncated = json.at("truncated").get<int>();
  model.observation_settings = json.value("observation_settings", std::string());
  model.policy_fingerprint = json.value("policy_fingerprint", std::string());
  for (const SummaryMetric& metric : SummaryMetrics()) {
    const nlohmann::json& metric_json = json.at("metrics").at(metric.key);
    const MeanConfidenceInterval t = ConfidenceIntervalFromJson(metric_json);
    // Summaries written before the in-range intervals existed have only the Student-t one.
    const Interval in_range = metric_json.contains("in_range")
                                  ? Interval{metric_json["in_range"].at("low").get<double>(),
                                             metric_json["in_range"].at("high").get<double>()}
                                  : Interval{t.low, t.high};
    model.metrics.push_back({metric.key, t, in_range});
  }
  return model;
}

}  // namespace

EvaluationReport MakeEvaluationReport(const std::string& scenarios,
                                      std::optional<std::uint64_t> seed,
                                      const std::vector<std::string>& names,
                                      const std::vector<std::string>& policies,
                                      const std::vector<std::vector<EpisodeMetrics>>& episodes) {
  EvaluationReport report{scenarios, seed, {}, {}};
  for (std::size_t m = 0; m < names.size(); ++m) {
    report.models.push_back(SummariseModel(names[m], policies[m], episodes[m]));
  }
  for (std::size_t first = 0; first < names.size(); ++first) {
    for (std::size_t second = first + 1; second < names.size(); ++second) {
      report.differences.push_back(
          CompareModels(names[first], episodes[first], names[second], episodes[second]));
    }
  }
  return report;
}

nlohmann::ordered_json EvaluationReportJson(const EvaluationReport& report) {
  nlohmann::ordered_json json;
  json["scenarios"] = report.scenarios;
  json["seed"] = report.seed ? nlohmann::ordered_json(*report.seed) : nlohmann::ordered_json();
  json["evaluator_build_id"] = report.evaluator_build_id;
  json["models"] = nlohmann::ordered_json::array();
  for (const ModelSummary& model : report.models) json["models"].push_back(ModelJson(model));
  json["paired_differences"] = nlohmann::ordered_json::array();
  for (const PairedDifference& difference : report.differences) {
    json["paired_differences"].push_back({{"first", difference.first},
                                          {"second", difference.second},
                                          {"metrics", MetricsJson(difference.metrics)}});
  }
  return json;
}

std::string EvaluationReportMarkdown(const EvaluationReport& report) {
  std::ostringstream markdown;
  const int episodes = report.models.empty() ? 0 : report.models.front().episodes;
  markdown << "Test results over " << episodes << " episodes ("
           << (report.scenarios == "test"
                   ? "test scenarios of master seed " + std::to_string(report.seed.value_or(0))
                   : std::string("scenario files"))
           << "), mean [95 % CI]: rates (collisions, goals reached) with the Wilson score "
              "interval, progress with the percentile bootstrap (2,000 resamples), the others "
              "with Student-t:\n\n"
           << SummaryTable(report.models, TableInterval::kInRange)
           << "\nThe same with Student-t 95 % CIs for every metric, as the paper's table reports "
              "them (they can leave [0, 100 %] for rates near 0 or 1):\n\n"
           << SummaryTable(report.models, TableInterval::kStudentT);
  if (!report.differences.empty()) {
    markdown << "\nPaired differences on the same episodes, first minus second, mean [95 % "
                "Student-t CI] (pp = percentage points; bold: the interval excludes 0):\n\n"
             << DifferenceTable(report.differences);
  }
  return markdown.str();
}

std::vector<ModelSummary> ReadModelSummaries(const std::filesystem::path& path) {
  std::ifstream file(path);
  if (!file) throw UserError(path.string() + ": cannot read the evaluation summary");
  const nlohmann::json json = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded()) throw UserError(path.string() + ": not valid JSON");
  std::vector<ModelSummary> models;
  try {
    for (const nlohmann::json& model : json.at("models")) models.push_back(ModelFromJson(model));
  } catch (const nlohmann::json::exception& error) {
    throw UserError(path.string() + ": not an evaluation summary (" + error.what() + ")");
  }
  return models;
}

}  // namespace colav

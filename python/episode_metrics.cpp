#include "python/episode_metrics.h"

#include <pybind11/numpy.h>

namespace colav::python {
namespace {

// The one list of the metrics, by name and field, in the order of evaluate's episodes.csv.
template <typename Visit>
void ForEachMetric(Visit&& visit) {
  visit("progress", &EpisodeMetrics::progress);
  visit("mean_abs_cte", &EpisodeMetrics::mean_abs_cte);
  visit("steps", &EpisodeMetrics::steps);
  visit("collision", &EpisodeMetrics::collision);
  visit("goal_reached", &EpisodeMetrics::goal_reached);
  visit("truncated", &EpisodeMetrics::truncated);
  visit("cumulative_reward", &EpisodeMetrics::cumulative_reward);
  visit("path_length", &EpisodeMetrics::path_length);
}

}  // namespace

py::dict MetricsDict(const EpisodeMetrics& metrics) {
  py::dict dict;
  ForEachMetric([&](const char* name, auto field) { dict[name] = metrics.*field; });
  return dict;
}

py::dict MetricColumns(const std::vector<std::optional<EpisodeMetrics>>& episodes) {
  py::dict columns;
  ForEachMetric([&](const char* name, auto field) {
    using Value = std::remove_reference_t<decltype(EpisodeMetrics{}.*field)>;
    py::array_t<Value> column(static_cast<py::ssize_t>(episodes.size()));
    Value* values = column.mutable_data();
    for (const std::optional<EpisodeMetrics>& episode : episodes) {
      *values++ = episode ? (*episode).*field : Value{};
    }
    columns[name] = column;
  });
  return columns;
}

}  // namespace colav::python

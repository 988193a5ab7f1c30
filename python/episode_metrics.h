// Episode records (EpisodeMetrics) as Python dictionaries: one episode's scalars, or a column per
// metric over the worlds of a batch.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <vector>

#include "env/environment_spec.h"

namespace colav::python {

namespace py = pybind11;

/// {"progress": float, "mean_abs_cte": float, "steps": int, "collision": bool, "goal_reached":
/// bool, "truncated": bool, "cumulative_reward": float, "path_length": float}
py::dict MetricsDict(const EpisodeMetrics& metrics);

/// The same keys, each a numpy array over the worlds; a world without an episode gets zeros.
py::dict MetricColumns(const std::vector<std::optional<EpisodeMetrics>>& episodes);

}  // namespace colav::python

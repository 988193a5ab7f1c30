// What the two batched environments of the Python module share: the result arrays of a batch,
// made once and written in place by the C++ side, the info dictionary of the episodes that ended,
// and the reading of action arrays.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <optional>
#include <vector>

#include "env/batched_environment.h"

namespace colav::python {

namespace py = pybind11;

using FloatActions = py::array_t<float, py::array::c_style>;
using DoubleActions = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// One set of result arrays of `rows` worlds and the pointers the C++ environments write through.
struct BatchArrays {
  BatchArrays(int rows, int observation_size);
  py::array_t<float> observations;
  py::array_t<float> final_observations;
  py::array_t<float> rewards;
  py::array_t<bool> terminated;
  py::array_t<bool> truncated;
  BatchedOutputs pointers;
};

/// Throws ValueError unless actions is [rows, kActionSize].
void RequireActionShape(const py::array& actions, int rows);

/// Calls use(array) with `actions` as a float32 array read in place if it is one, otherwise
/// converted to float64 (TypeError if it holds no numbers); returns what use returns.
template <typename Use>
auto WithActionArray(const py::object& actions, const Use& use) {
  if (py::isinstance<FloatActions>(actions)) {
    return use(py::reinterpret_borrow<FloatActions>(actions));
  }
  const DoubleActions converted = DoubleActions::ensure(actions);
  if (!converted) throw py::type_error("actions: expected an array of numbers");
  return use(converted);
}

/// How many of `episodes` ended (are set).
int CountFinished(const std::vector<std::optional<EpisodeMetrics>>& episodes);

/// For the rows whose episode ended: {"final_obs": final_observations, "_final_obs": mask,
/// "episode_metrics": {metric: [rows]}, "_episode_metrics": mask} (Gymnasium's vector info
/// layout: values of other rows are meaningless).
py::dict FinishedEpisodesInfo(const std::vector<std::optional<EpisodeMetrics>>& episodes,
                              const py::array_t<float>& final_observations);

}  // namespace colav::python

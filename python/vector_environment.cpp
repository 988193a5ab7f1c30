#include "python/vector_environment.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "python/episode_metrics.h"
#include "src/threads/thread_pool.h"

namespace colav::python {
namespace {

using FloatActions = py::array_t<float, py::array::c_style>;
using DoubleActions = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string ShapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    text += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

void RequireActionShape(const py::array& actions, int num_envs) {
  if (actions.ndim() != 2 || actions.shape(0) != num_envs || actions.shape(1) != kActionSize) {
    throw py::value_error("actions: expected shape (" + std::to_string(num_envs) + ", " +
                          std::to_string(kActionSize) + "), got " + ShapeText(actions));
  }
}

}  // namespace

VectorEnvironment::OutputArrays::OutputArrays(int num_envs, int observation_size)
    : observations({num_envs, observation_size}),
      final_observations({num_envs, observation_size}),
      rewards(num_envs),
      terminated(num_envs),
      truncated(num_envs) {
  std::fill_n(final_observations.mutable_data(), final_observations.size(), 0.0f);
  static_assert(sizeof(bool) == sizeof(std::uint8_t), "numpy bools are written as bytes");
  pointers = {observations.mutable_data(), final_observations.mutable_data(),
              rewards.mutable_data(), reinterpret_cast<std::uint8_t*>(terminated.mutable_data()),
              reinterpret_cast<std::uint8_t*>(truncated.mutable_data())};
}

VectorEnvironment::VectorEnvironment(const ResolvedSettings& settings, int num_envs,
                                     std::uint64_t seed, int num_threads)
    : envs_(settings.config, num_envs, ThreadCountOrAllCores(num_threads), seed),
      outputs_{OutputArrays(num_envs, envs_.observation_size()),
               OutputArrays(num_envs, envs_.observation_size())} {}

VectorEnvironment::VectorEnvironment(const ResolvedSettings& settings,
                                     const std::vector<Scenario>& scenarios, int num_threads)
    : envs_(settings.config, scenarios, ThreadCountOrAllCores(num_threads)),
      outputs_{OutputArrays(envs_.num_envs(), envs_.observation_size()),
               OutputArrays(envs_.num_envs(), envs_.observation_size())} {}

VectorEnvironment::OutputArrays& VectorEnvironment::NextOutputs() {
  current_ = 1 - current_;
  return outputs_[current_];
}

py::array_t<float> VectorEnvironment::Reset(std::optional<std::uint64_t> seed) {
  const OutputArrays& outputs = NextOutputs();
  {
    const py::gil_scoped_release release;
    envs_.Reset(seed, outputs.pointers);
  }
  started_ = true;
  return outputs.observations;
}

template <typename Actions>
int VectorEnvironment::StepWith(const Actions& actions, const OutputArrays& outputs) {
  RequireActionShape(actions, num_envs());
  const auto* values = actions.data();
  const py::gil_scoped_release release;
  envs_.Step(values, outputs.pointers);
  const auto& finished = envs_.finished_episodes();
  return static_cast<int>(
      std::count_if(finished.begin(), finished.end(), [](const auto& e) { return e.has_value(); }));
}

py::tuple VectorEnvironment::Step(const py::object& actions) {
  if (!started_) throw std::runtime_error("step() before reset(): call reset() first");
  const OutputArrays& outputs = NextOutputs();
  int finished = 0;
  if (py::isinstance<FloatActions>(actions)) {
    finished = StepWith(py::reinterpret_borrow<FloatActions>(actions), outputs);
  } else {
    const DoubleActions converted = DoubleActions::ensure(actions);
    if (!converted) throw py::type_error("actions: expected an array of numbers");
    finished = StepWith(converted, outputs);
  }
  return py::make_tuple(outputs.observations, outputs.rewards, outputs.terminated,
                        outputs.truncated, finished);
}

py::dict VectorEnvironment::FinishedEpisodes() const {
  const auto& episodes = envs_.finished_episodes();
  py::array_t<bool> mask(static_cast<py::ssize_t>(episodes.size()));
  std::transform(episodes.begin(), episodes.end(), mask.mutable_data(),
                 [](const auto& episode) { return episode.has_value(); });
  py::dict info;
  info["final_obs"] = outputs_[current_].final_observations;
  info["_final_obs"] = mask;
  info["episode_metrics"] = MetricColumns(episodes);
  info["_episode_metrics"] = mask;
  return info;
}

void BindVectorEnvironment(py::module_& module) {
  py::class_<VectorEnvironment>(module, "VectorEnvironment")
      .def(py::init<const ResolvedSettings&, int, std::uint64_t, int>(), py::arg("settings"),
           py::arg("num_envs"), py::arg("seed"), py::arg("num_threads"))
      .def(py::init<const ResolvedSettings&, const std::vector<Scenario>&, int>(),
           py::arg("settings"), py::arg("scenarios"), py::arg("num_threads"))
      .def_property_readonly("num_envs", &VectorEnvironment::num_envs)
      .def_property_readonly("observation_size", &VectorEnvironment::observation_size)
      .def("reset", &VectorEnvironment::Reset, py::arg("seed"))
      .def("step", &VectorEnvironment::Step, py::arg("actions"))
      .def("finished_episodes", &VectorEnvironment::FinishedEpisodes);
}

}  // namespace colav::python

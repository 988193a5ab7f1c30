#include "python/single_environment.h"

#include <pybind11/stl.h>

#include <memory>
#include <stdexcept>

#include "env/batched_environment.h"
#include "env/scenario_file.h"
#include "env/training_scenario.h"
#include "python/episode_metrics.h"

namespace colav::python {
namespace {

using DoubleAction = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::shared_ptr<const ScenarioSource> SourceOf(std::optional<Scenario> scenario) {
  if (scenario) return std::make_shared<FixedScenarioSource>(std::move(*scenario));
  return std::make_shared<TrainingScenarioGenerator>();
}

template <typename Values>
py::array_t<double> DoubleArray(const Values& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

}  // namespace

SingleEnvironment::SingleEnvironment(const ResolvedSettings& settings,
                                     std::optional<Scenario> scenario, std::uint64_t seed)
    : environment_(settings.config, SourceOf(std::move(scenario))), seed_(seed) {}

py::array_t<float> SingleEnvironment::Reset(std::optional<std::uint64_t> seed) {
  if (seed) {
    seed_ = *seed;
    episode_ = 0;
  } else if (started_) {
    ++episode_;
  }
  started_ = episode_running_ = true;
  py::array_t<float> observation(kObservationSize);
  environment_.Reset(TrainingEpisodeSeed(seed_, 0, episode_), observation.mutable_data());
  return observation;
}

py::tuple SingleEnvironment::Step(const py::object& action) {
  if (!episode_running_) {
    throw std::runtime_error(started_ ? "step() after the episode ended: call reset() first"
                                      : "step() before reset(): call reset() first");
  }
  const DoubleAction values = DoubleAction::ensure(action);
  if (!values || values.size() != kActionSize) {
    throw py::value_error("action: expected 2 numbers (thrust, yaw moment)");
  }
  py::array_t<float> observation(kObservationSize);
  const StepResult result = environment_.Step(values.data(), observation.mutable_data());
  episode_running_ = !(result.terminated || result.truncated);
  return py::make_tuple(observation, result.reward, result.terminated, result.truncated,
                        result.episode ? py::object(MetricsDict(*result.episode)) : py::none());
}

py::dict SingleEnvironment::State() const {
  const World& world = environment_.world();
  const NavigationState& navigation = world.navigation();
  py::dict state;
  state["vessel"] = DoubleArray(world.vessel());
  state["cross_track_error"] = navigation.cross_track_error;
  state["heading_error"] = navigation.heading_error;
  state["look_ahead_heading_error"] = navigation.look_ahead_heading_error;
  state["progress"] = navigation.progress;
  state["collision"] = world.collision();
  state["ranges"] = DoubleArray(world.ranges());
  return state;
}

void BindSingleEnvironment(py::module_& module) {
  py::class_<SingleEnvironment>(module, "SingleEnvironment")
      .def(py::init<const ResolvedSettings&, std::optional<Scenario>, std::uint64_t>(),
           py::arg("settings"), py::arg("scenario"), py::arg("seed"))
      .def("reset", &SingleEnvironment::Reset, py::arg("seed"))
      .def("step", &SingleEnvironment::Step, py::arg("action"))
      .def("state", &SingleEnvironment::State);
}

}  // namespace colav::python

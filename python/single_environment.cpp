#include "python/single_environment.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <utility>

#include "env/batched_environment.h"
#include "env/scenario_file.h"
#include "env/training_scenario.h"
#include "eval/replay/scene_frame.h"
#include "python/episode_metrics.h"

namespace colav::python {
namespace {

using DoubleAction = py::array_t<double, py::array::c_style | py::array::forcecast>;

template <typename Values>
py::array_t<double> DoubleArray(const Values& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

}  // namespace

SingleEnvironment::SingleEnvironment(const ResolvedSettings& settings, const ResolvedWorld& world,
                                     std::uint64_t seed, bool render)
    : SingleEnvironment(settings, std::make_shared<TrainingScenarioGenerator>(world.config),
                        "training world", seed, render) {}

SingleEnvironment::SingleEnvironment(const ResolvedSettings& settings, const Scenario& scenario,
                                     std::uint64_t seed, bool render)
    : SingleEnvironment(settings, std::make_shared<FixedScenarioSource>(scenario), scenario.name,
                        seed, render) {}

SingleEnvironment::SingleEnvironment(const ResolvedSettings& settings,
                                     std::shared_ptr<const ScenarioSource> source,
                                     std::string scene_name, std::uint64_t seed, bool render)
    : environment_(settings.config, std::move(source)),
      seed_(seed),
      render_(render),
      scene_name_(std::move(scene_name)) {}

py::array_t<float> SingleEnvironment::Reset(std::optional<std::uint64_t> seed) {
  if (seed) {
    seed_ = *seed;
    episode_ = 0;
  } else if (started_) {
    ++episode_;
  }
  started_ = episode_running_ = true;
  py::array_t<float> observation(observation_size());
  environment_.Reset(TrainingEpisodeSeed(seed_, 0, episode_), observation.mutable_data());
  if (render_) recorder_.emplace(environment_.world(), scene_name_, "agent");
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
  py::array_t<float> observation(observation_size());
  const StepResult result = environment_.Step(values.data(), observation.mutable_data());
  if (recorder_) recorder_->Record(environment_.world(), values.data(), result);
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
  state["path_length"] = world.path().length();
  state["collision"] = world.collision();
  state["ranges"] = DoubleArray(world.ranges());
  return state;
}

py::array_t<std::uint8_t> SingleEnvironment::Render(int width, int height) const {
  if (!render_) throw std::runtime_error("render(): the environment was made without rendering");
  if (!recorder_) throw std::runtime_error("render() before reset(): call reset() first");
  if (width < 16 || height < 16 || width > 4096 || height > 4096) {
    throw py::value_error("render(): width and height must be in [16, 4096]");
  }
  const Replay& replay = recorder_->replay();
  const int step = ReplayLength(replay) - 1;
  const RgbImage image = DrawFrame(replay, step, FollowView(replay, 0, step, width, height));
  py::array_t<std::uint8_t> pixels({height, width, 3});
  std::copy(image.rgb.begin(), image.rgb.end(), pixels.mutable_data());
  return pixels;
}

void BindSingleEnvironment(py::module_& module) {
  py::class_<SingleEnvironment>(module, "SingleEnvironment")
      .def(py::init<const ResolvedSettings&, const ResolvedWorld&, std::uint64_t, bool>(),
           py::arg("settings"), py::arg("world"), py::arg("seed"), py::arg("render") = false)
      .def(py::init<const ResolvedSettings&, const Scenario&, std::uint64_t, bool>(),
           py::arg("settings"), py::arg("scenario"), py::arg("seed"), py::arg("render") = false)
      .def_property_readonly("observation_size", &SingleEnvironment::observation_size)
      .def("reset", &SingleEnvironment::Reset, py::arg("seed"))
      .def("step", &SingleEnvironment::Step, py::arg("action"))
      .def("state", &SingleEnvironment::State)
      .def("render", &SingleEnvironment::Render, py::arg("width"), py::arg("height"));
}

}  // namespace colav::python

#include "python/vector_environment.h"

#include <pybind11/stl.h>

#include <stdexcept>
#include <vector>

#include "env/training_scenario_config.h"
#include "src/threads/thread_pool.h"

namespace colav::python {

VectorEnvironment::VectorEnvironment(const ResolvedSettings& settings, const ResolvedWorld& world,
                                     const ResolvedWorld& world2, double world2_share, int num_envs,
                                     std::uint64_t seed, int num_threads)
    : envs_(settings.config, MixedWorlds(world.config, world2.config, world2_share, num_envs),
            ThreadCountOrAllCores(num_threads), seed),
      outputs_{BatchArrays(num_envs, envs_.observation_size()),
               BatchArrays(num_envs, envs_.observation_size())} {}

VectorEnvironment::VectorEnvironment(const ResolvedSettings& settings,
                                     const std::vector<Scenario>& scenarios, int num_threads)
    : envs_(settings.config, scenarios, ThreadCountOrAllCores(num_threads)),
      outputs_{BatchArrays(envs_.num_envs(), envs_.observation_size()),
               BatchArrays(envs_.num_envs(), envs_.observation_size())} {}

BatchArrays& VectorEnvironment::NextOutputs() {
  current_ = 1 - current_;
  return outputs_[current_];
}

py::array_t<float> VectorEnvironment::Reset(std::optional<std::uint64_t> seed) {
  const BatchArrays& outputs = NextOutputs();
  {
    const py::gil_scoped_release release;
    envs_.Reset(seed, outputs.pointers);
  }
  started_ = true;
  return outputs.observations;
}

template <typename Actions>
int VectorEnvironment::StepWith(const Actions& actions, const BatchArrays& outputs) {
  RequireActionShape(actions, num_envs());
  const auto* values = actions.data();
  const py::gil_scoped_release release;
  envs_.Step(values, outputs.pointers);
  return CountFinished(envs_.finished_episodes());
}

py::tuple VectorEnvironment::Step(const py::object& actions) {
  if (!started_) throw std::runtime_error("step() before reset(): call reset() first");
  const BatchArrays& outputs = NextOutputs();
  const int finished =
      WithActionArray(actions, [&](const auto& array) { return StepWith(array, outputs); });
  return py::make_tuple(outputs.observations, outputs.rewards, outputs.terminated,
                        outputs.truncated, finished);
}

py::dict VectorEnvironment::FinishedEpisodes() const {
  return FinishedEpisodesInfo(envs_.finished_episodes(), outputs_[current_].final_observations);
}

void BindVectorEnvironment(py::module_& module) {
  py::class_<VectorEnvironment>(module, "VectorEnvironment")
      .def(py::init<const ResolvedSettings&, const ResolvedWorld&, const ResolvedWorld&, double,
                    int, std::uint64_t, int>(),
           py::arg("settings"), py::arg("world"), py::arg("world2"), py::arg("world2_share"),
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

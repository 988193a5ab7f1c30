// _colav: the extension module behind the Python package `colav` (python/colav/). It links the
// simulator (colav_env) and nothing of LibTorch.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <map>
#include <string>
#include <vector>

#include "env/batched_environment.h"
#include "env/scenario_file.h"
#include "env/training_scenario.h"
#include "python/async_vector_environment.h"
#include "python/settings.h"
#include "python/single_environment.h"
#include "python/vector_environment.h"
#include "src/error.h"

namespace colav::python {
namespace {

py::object PythonValue(const ConfigValue& value) {
  return std::visit([](const auto& alternative) { return py::cast(alternative); }, value);
}

template <typename Options>
py::dict ValuesDict(const Resolved<Options>& resolved) {
  py::dict values;
  for (const auto& [name, value] : resolved.values) values[name.c_str()] = PythonValue(value);
  return values;
}

py::dict DocsDict(const std::vector<SettingDoc>& docs) {
  py::dict dict;
  for (const SettingDoc& doc : docs) {
    dict[doc.name.c_str()] = py::make_tuple(PythonValue(doc.default_value), doc.doc);
  }
  return dict;
}

void BindSettings(py::module_& module) {
  py::class_<ResolvedSettings>(module, "ResolvedSettings")
      .def_property_readonly("values", &ValuesDict<EnvironmentConfig>);
  py::class_<ResolvedWorld>(module, "ResolvedWorld")
      .def_property_readonly("values", &ValuesDict<TrainingScenarioConfig>);
  module.def("resolve_settings", &ResolveSettings, py::arg("texts"), py::arg("origin"),
             "The environment configuration of {keyword: value text}, validated as the programs "
             "validate env.* keys (ValueError naming the key).");
  module.def("resolve_world", &ResolveWorld, py::arg("texts"), py::arg("origin"),
             py::arg("section"),
             "A kind of training world of {keyword: value text}, validated as train_ppo "
             "validates its SECTION.* keys (world or world2; ValueError naming the key).");
  module.def(
      "setting_docs", [] { return DocsDict(SettingDocs()); },
      "{keyword: (default, doc)} of every environment setting.");
  module.def(
      "world_setting_docs", [] { return DocsDict(WorldSettingDocs()); },
      "{keyword: (default, doc)} of every training world setting.");
}

void BindScenarios(py::module_& module) {
  py::class_<Scenario>(module, "Scenario")
      .def_readonly("name", &Scenario::name)
      .def_property_readonly(
          "num_moving", [](const Scenario& scenario) { return scenario.dynamic_obstacles.size(); })
      .def_property_readonly(
          "num_static", [](const Scenario& scenario) { return scenario.static_obstacles.size(); });
  module.def(
      "load_scenario_file", [](const std::string& path) { return LoadScenarioFile(path); },
      py::arg("path"), "A scenario file, validated (ValueError naming the file and key).");
  module.def(
      "training_scenario",
      [](std::uint64_t seed, const ResolvedWorld& world) {
        return TrainingScenarioGenerator(world.config).Make(seed);
      },
      py::arg("seed"), py::arg("world"),
      "The training world of this seed (with the paper's world, simulate --training-seed).");
  // The seed of episode k of world env_id of a training run (env/batched_environment.h).
  module.def("training_episode_seed", &TrainingEpisodeSeed, py::arg("seed"), py::arg("env_id"),
             py::arg("episode"));
  // The test scenarios of evaluate (env/batched_environment.h, TestScenarioSeed).
  module.def("test_scenario_seed", &TestScenarioSeed, py::arg("master_seed"), py::arg("k"));
}

}  // namespace
}  // namespace colav::python

PYBIND11_MODULE(_colav, module) {
  module.doc() = "The colav simulator (C++); use the package `colav`, not this module.";
  // Bad input (a setting, a scenario file) is a ValueError whose message names it.
  pybind11::register_exception<colav::UserError>(module, "UserError", PyExc_ValueError);
  colav::python::BindSettings(module);
  colav::python::BindScenarios(module);
  colav::python::BindVectorEnvironment(module);
  colav::python::BindAsyncVectorEnvironment(module);
  colav::python::BindSingleEnvironment(module);
}

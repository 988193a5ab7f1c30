// _colav: the extension module behind the Python package `colav` (python/colav/). It links the
// simulator (colav_env) and nothing of LibTorch.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <map>
#include <string>

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

py::dict SettingsDict(const ResolvedSettings& settings) {
  py::dict values;
  for (const auto& [name, value] : settings.values) values[name.c_str()] = PythonValue(value);
  return values;
}

void BindSettings(py::module_& module) {
  py::class_<ResolvedSettings>(module, "ResolvedSettings")
      .def_property_readonly("values", &SettingsDict);
  module.def("resolve_settings", &ResolveSettings, py::arg("texts"), py::arg("origin"),
             "The environment configuration of {keyword: value text}, validated as the programs "
             "validate env.* keys (ValueError naming the key).");
  module.def(
      "setting_docs",
      [] {
        py::dict docs;
        for (const SettingDoc& doc : SettingDocs()) {
          docs[doc.name.c_str()] = py::make_tuple(PythonValue(doc.default_value), doc.doc);
        }
        return docs;
      },
      "{keyword: (default, doc)} of every environment setting.");
}

void BindScenarios(py::module_& module) {
  py::class_<Scenario>(module, "Scenario").def_readonly("name", &Scenario::name);
  module.def(
      "load_scenario_file", [](const std::string& path) { return LoadScenarioFile(path); },
      py::arg("path"), "A scenario file, validated (ValueError naming the file and key).");
  module.def(
      "training_scenario",
      [](std::uint64_t seed) { return TrainingScenarioGenerator().Make(seed); }, py::arg("seed"),
      "The paper's training world of this seed (simulate --training-seed).");
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

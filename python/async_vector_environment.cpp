#include "python/async_vector_environment.h"

#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "env/training_scenario_config.h"
#include "src/threads/thread_pool.h"

namespace colav::python {
namespace {

using Int32Ids = py::array_t<std::int32_t, py::array::c_style>;
using Int64Ids = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

// env_ids as int32 (read in place if it is a contiguous int32 array, as recv returns them), each
// checked to be a world's id (ValueError naming the first that is not).
template <typename Ids>
void CopyEnvIds(const Ids& values, int num_envs, std::vector<std::int32_t>* ids) {
  ids->resize(values.size());
  for (py::ssize_t k = 0; k < values.size(); ++k) {
    const std::int64_t id = values.data()[k];
    if (id < 0 || id >= num_envs) {
      throw py::value_error("env_id: " + std::to_string(id) + " is outside [0, " +
                            std::to_string(num_envs) + ")");
    }
    (*ids)[k] = static_cast<std::int32_t>(id);
  }
}

void ReadEnvIds(const py::object& env_ids, int num_envs, std::vector<std::int32_t>* ids) {
  const py::array array = py::array::ensure(env_ids);
  if (!array || array.ndim() != 1 || (array.dtype().kind() != 'i' && array.dtype().kind() != 'u')) {
    throw py::type_error("env_id: expected a 1-D array of integers");
  }
  if (py::isinstance<Int32Ids>(array)) {
    CopyEnvIds(py::reinterpret_borrow<Int32Ids>(array), num_envs, ids);
  } else {
    CopyEnvIds(Int64Ids::ensure(array), num_envs, ids);
  }
}

}  // namespace

AsyncVectorEnvironment::AsyncVectorEnvironment(const ResolvedSettings& settings,
                                               const ResolvedWorld& world,
                                               const ResolvedWorld& world2, double world2_share,
                                               int num_envs, int batch_size, std::uint64_t seed,
                                               int num_threads)
    : pool_(settings.config, MixedWorlds(world.config, world2.config, world2_share, num_envs),
            batch_size, ThreadCountOrAllCores(num_threads), seed),
      outputs_{BatchArrays(batch_size, pool_.observation_size()),
               BatchArrays(batch_size, pool_.observation_size())},
      env_ids_{py::array_t<std::int32_t>(batch_size), py::array_t<std::int32_t>(batch_size)} {}

AsyncVectorEnvironment::AsyncVectorEnvironment(const ResolvedSettings& settings,
                                               const std::vector<Scenario>& scenarios,
                                               int batch_size, int num_threads)
    : pool_(settings.config, scenarios, batch_size, ThreadCountOrAllCores(num_threads)),
      outputs_{BatchArrays(batch_size, pool_.observation_size()),
               BatchArrays(batch_size, pool_.observation_size())},
      env_ids_{py::array_t<std::int32_t>(batch_size), py::array_t<std::int32_t>(batch_size)} {}

void AsyncVectorEnvironment::AsyncReset(std::optional<std::uint64_t> seed) {
  const py::gil_scoped_release release;  // the steps in flight are played first
  pool_.Reset(seed);
}

void AsyncVectorEnvironment::Send(const py::object& actions, const py::object& env_ids) {
  ReadEnvIds(env_ids, num_envs(), &sent_ids_);
  WithActionArray(actions, [this](const auto& array) {
    RequireActionShape(array, static_cast<int>(sent_ids_.size()));
    pool_.Send(array.data(), sent_ids_.data(), static_cast<int>(sent_ids_.size()));
    return 0;
  });
}

py::tuple AsyncVectorEnvironment::Step(const py::object& actions, const py::object& env_ids) {
  Send(actions, env_ids);
  return Recv();
}

py::tuple AsyncVectorEnvironment::Recv() {
  current_ = 1 - current_;
  const BatchArrays& outputs = outputs_[current_];
  py::array_t<std::int32_t>& env_ids = env_ids_[current_];
  const AsyncBatchOutputs pointers{outputs.pointers, env_ids.mutable_data()};
  {
    const py::gil_scoped_release release;
    pool_.Recv(pointers);
  }
  return py::make_tuple(outputs.observations, outputs.rewards, outputs.terminated,
                        outputs.truncated, env_ids, CountFinished(pool_.finished_episodes()));
}

py::dict AsyncVectorEnvironment::FinishedEpisodes() const {
  return FinishedEpisodesInfo(pool_.finished_episodes(), outputs_[current_].final_observations);
}

void BindAsyncVectorEnvironment(py::module_& module) {
  py::class_<AsyncVectorEnvironment>(module, "AsyncVectorEnvironment")
      .def(py::init<const ResolvedSettings&, const ResolvedWorld&, const ResolvedWorld&, double,
                    int, int, std::uint64_t, int>(),
           py::arg("settings"), py::arg("world"), py::arg("world2"), py::arg("world2_share"),
           py::arg("num_envs"), py::arg("batch_size"), py::arg("seed"), py::arg("num_threads"))
      .def(py::init<const ResolvedSettings&, const std::vector<Scenario>&, int, int>(),
           py::arg("settings"), py::arg("scenarios"), py::arg("batch_size"), py::arg("num_threads"))
      .def_property_readonly("num_envs", &AsyncVectorEnvironment::num_envs)
      .def_property_readonly("batch_size", &AsyncVectorEnvironment::batch_size)
      .def_property_readonly("observation_size", &AsyncVectorEnvironment::observation_size)
      .def("async_reset", &AsyncVectorEnvironment::AsyncReset, py::arg("seed"))
      .def("send", &AsyncVectorEnvironment::Send, py::arg("actions"), py::arg("env_ids"))
      .def("recv", &AsyncVectorEnvironment::Recv)
      .def("step", &AsyncVectorEnvironment::Step, py::arg("actions"), py::arg("env_ids"))
      .def("finished_episodes", &AsyncVectorEnvironment::FinishedEpisodes);
}

}  // namespace colav::python

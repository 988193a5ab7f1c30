// The C++ side of colav.AsyncVectorEnv: an AsyncEnvironmentPool (EnvPool's asynchronous mode)
// whose batches land in numpy arrays made once, with the GIL released while it waits and steps.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "env/async_environment.h"
#include "python/batch_arrays.h"
#include "python/settings.h"

namespace colav::python {

namespace py = pybind11;

class AsyncVectorEnvironment {
 public:
  /// num_envs training worlds of `world` and `world2` (as VectorEnvironment's) returned
  /// batch_size at a time, stepped on num_threads threads (0: one per core) counting the one
  /// calling recv.
  AsyncVectorEnvironment(const ResolvedSettings& settings, const ResolvedWorld& world,
                         const ResolvedWorld& world2, double world2_share, int num_envs,
                         int batch_size, std::uint64_t seed, int num_threads);
  /// One world per scenario, replaying it in every episode.
  AsyncVectorEnvironment(const ResolvedSettings& settings, const std::vector<Scenario>& scenarios,
                         int batch_size, int num_threads);

  int num_envs() const { return pool_.num_envs(); }
  int batch_size() const { return pool_.batch_size(); }
  int observation_size() const { return pool_.observation_size(); }

  /// Queues new episodes in every world (AsyncEnvironmentPool::Reset).
  void AsyncReset(std::optional<std::uint64_t> seed);

  /// Queues a step of the worlds env_ids (1-D integers) with actions [len(env_ids), 2] (float32
  /// is read in place, other dtypes are converted).
  void Send(const py::object& actions, const py::object& env_ids);

  /// The next batch_size worlds done: (observations, rewards, terminated, truncated, env_ids,
  /// number of episodes that ended). The arrays are reused: the next recv writes to a second set,
  /// the one after that overwrites these.
  py::tuple Recv();

  /// Send, then Recv, in one call.
  py::tuple Step(const py::object& actions, const py::object& env_ids);

  /// For the rows of the last recv whose episode ended, as VectorEnvironment::FinishedEpisodes.
  py::dict FinishedEpisodes() const;

 private:
  AsyncEnvironmentPool pool_;
  std::array<BatchArrays, 2> outputs_;
  std::array<py::array_t<std::int32_t>, 2> env_ids_;
  int current_ = 0;
  std::vector<std::int32_t> sent_ids_;  // the env ids of a send, checked and narrowed
};

/// Registers AsyncVectorEnvironment as _colav.AsyncVectorEnvironment.
void BindAsyncVectorEnvironment(py::module_& module);

}  // namespace colav::python

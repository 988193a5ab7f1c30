// The C++ side of colav.VectorEnv: a BatchedEnvironment whose results land directly in numpy
// arrays made once, with the GIL released while the worlds step.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "env/batched_environment.h"
#include "python/batch_arrays.h"
#include "python/settings.h"

namespace colav::python {

namespace py = pybind11;

class VectorEnvironment {
 public:
  /// num_envs training worlds, of `world` but for the world2_share of them (the last ones) of
  /// `world2` (MixedWorlds; episode k of world i from TrainingEpisodeSeed(seed, i, k)), on
  /// num_threads threads (0: one per core).
  VectorEnvironment(const ResolvedSettings& settings, const ResolvedWorld& world,
                    const ResolvedWorld& world2, double world2_share, int num_envs,
                    std::uint64_t seed, int num_threads);
  /// One world per scenario, replaying it in every episode.
  VectorEnvironment(const ResolvedSettings& settings, const std::vector<Scenario>& scenarios,
                    int num_threads);

  int num_envs() const { return envs_.num_envs(); }
  /// Floats per observation row: ObservationSize of the environment's settings.
  int observation_size() const { return envs_.observation_size(); }

  /// New episodes in every world (see BatchedEnvironment::Reset); returns the observations.
  py::array_t<float> Reset(std::optional<std::uint64_t> seed);

  /// Steps every world (after a first Reset) with actions [num_envs, 2] (float32 is used in
  /// place, other dtypes are converted); returns (observations, rewards, terminated, truncated,
  /// number of episodes that ended). The arrays are reused: the next step writes to a second set,
  /// the one after that overwrites these.
  py::tuple Step(const py::object& actions);

  /// For the worlds whose episode ended on the last step: {"final_obs": [N, observation_size],
  /// "_final_obs": mask [N], "episode_metrics": {metric: [N]}, "_episode_metrics": mask [N]}
  /// (Gymnasium's vector info layout: values of other worlds are meaningless).
  py::dict FinishedEpisodes() const;

 private:
  BatchArrays& NextOutputs();
  template <typename Actions>
  int StepWith(const Actions& actions, const BatchArrays& outputs);

  BatchedEnvironment envs_;
  std::array<BatchArrays, 2> outputs_;
  int current_ = 0;
  bool started_ = false;  // stepping needs a first reset
};

/// Registers VectorEnvironment as _colav.VectorEnvironment.
void BindVectorEnvironment(py::module_& module);

}  // namespace colav::python

// The C++ side of colav.Env: one world, stepped in double precision exactly as `simulate` steps
// it, with its state readable for traces and pictures.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "env/environment.h"
#include "eval/replay/replay_recorder.h"
#include "python/settings.h"

namespace colav::python {

namespace py = pybind11;

class SingleEnvironment {
 public:
  /// Training worlds of `world`: episode k is the world of TrainingEpisodeSeed(seed, 0, k), as
  /// world 0 of a VectorEnvironment with the same seed and world. With `render`, each episode is
  /// recorded for Render.
  SingleEnvironment(const ResolvedSettings& settings, const ResolvedWorld& world,
                    std::uint64_t seed, bool render);
  /// Every episode replays `scenario`; `render` as above.
  SingleEnvironment(const ResolvedSettings& settings, const Scenario& scenario, std::uint64_t seed,
                    bool render);

  /// Starts the next episode (with a seed: episode 0 of that seed); returns its observation.
  py::array_t<float> Reset(std::optional<std::uint64_t> seed);

  /// Floats per observation: ObservationSize of the environment's settings.
  int observation_size() const { return ObservationSize(environment_.config()); }

  /// Advances one second under `action` (2 numbers, clipped to [-1, 1]); returns (observation,
  /// reward, terminated, truncated, episode metrics or None). A step after the episode ended and
  /// before a reset is an error.
  py::tuple Step(const py::object& action);

  /// {"vessel": [x, y, psi, u, v, r], "cross_track_error", "heading_error",
  /// "look_ahead_heading_error", "progress", "path_length", "collision", "ranges": [180]}: the
  /// world after the last reset or step (the columns of a `simulate` trace, and the path's length
  /// L, so that L (1 - progress) is the path left).
  py::dict State() const;

  /// The scene now (the episode's track so far) as a height x width x 3 uint8 array, drawn as
  /// the replay frames are (eval/replay/scene_frame.h, follow view).
  py::array_t<std::uint8_t> Render(int width, int height) const;

 private:
  SingleEnvironment(const ResolvedSettings& settings, std::shared_ptr<const ScenarioSource> source,
                    std::string scene_name, std::uint64_t seed, bool render);

  Environment environment_;
  std::uint64_t seed_;
  std::uint64_t episode_ = 0;
  bool started_ = false;
  bool episode_running_ = false;
  bool render_;
  std::string scene_name_;
  std::optional<ReplayRecorder> recorder_;  ///< the episode so far, with render
};

/// Registers SingleEnvironment as _colav.SingleEnvironment.
void BindSingleEnvironment(py::module_& module);

}  // namespace colav::python

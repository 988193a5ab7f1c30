// Rows of step results in memory an environment owns: what BatchedEnvironment's Reset and Step,
// and AsyncEnvironmentPool's Recv, write when the caller gives no outputs of its own.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "env/environment_spec.h"

namespace colav {

/// Where a Reset, Step or Recv writes its results: one row per world (or per batch row), in
/// memory the caller owns (a Python binding's numpy arrays, say), so results need not be copied.
struct BatchedOutputs {
  float* observations = nullptr;        ///< rows x ObservationSize(config)
  float* final_observations = nullptr;  ///< rows x ObservationSize(config); valid where done
  float* rewards = nullptr;             ///< rows
  std::uint8_t* terminated = nullptr;   ///< rows, 0 or 1
  std::uint8_t* truncated = nullptr;    ///< rows, 0 or 1
};

/// The results of the last call that wrote to the environment's own buffers, and the episode
/// records of the last call whichever outputs it wrote to.
class OwnedStepResults {
 public:
  /// rows x observation size
  const float* observations() const { return observations_.data(); }
  /// valid where done
  const float* final_observations() const { return final_observations_.data(); }
  const float* rewards() const { return rewards_.data(); }
  const std::uint8_t* terminated() const { return terminated_.data(); }
  const std::uint8_t* truncated() const { return truncated_.data(); }
  /// Per row: the record of the episode that ended on the last call, if one did (whichever
  /// outputs that call wrote to).
  const std::vector<std::optional<EpisodeMetrics>>& finished_episodes() const {
    return finished_episodes_;
  }

 protected:
  OwnedStepResults(int rows, int observation_size)
      : finished_episodes_(rows),
        observations_(static_cast<std::size_t>(rows) * observation_size, 0.0f),
        final_observations_(observations_.size(), 0.0f),
        rewards_(rows, 0.0f),
        terminated_(rows, 0),
        truncated_(rows, 0) {}

  /// The own buffers as outputs to write to.
  BatchedOutputs OwnOutputs() {
    return {observations_.data(), final_observations_.data(), rewards_.data(), terminated_.data(),
            truncated_.data()};
  }

  std::vector<std::optional<EpisodeMetrics>> finished_episodes_;

 private:
  std::vector<float> observations_;
  std::vector<float> final_observations_;
  std::vector<float> rewards_;
  std::vector<std::uint8_t> terminated_;
  std::vector<std::uint8_t> truncated_;
};

}  // namespace colav

// N training worlds stepped together by a thread pool, auto-resetting (EnvPool style).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "env/environment_spec.h"

namespace colav {

class Environment;
class ThreadPool;

/// The seed episode `episode` (counted from 0) of world `world` of a BatchedEnvironment built
/// with `seed` is generated from.
std::uint64_t TrainingEpisodeSeed(std::uint64_t seed, int world, std::uint64_t episode);

class BatchedEnvironment {
 public:
  /// num_envs worlds of the paper's training scenario; episode k of world i is generated from
  /// TrainingEpisodeSeed(seed, i, k), so a run is a pure function of `seed`.
  BatchedEnvironment(const EnvironmentConfig& config, int num_envs, int num_threads,
                     std::uint64_t seed);
  ~BatchedEnvironment();
  BatchedEnvironment(const BatchedEnvironment&) = delete;
  BatchedEnvironment& operator=(const BatchedEnvironment&) = delete;

  int num_envs() const { return num_envs_; }

  /// Starts a new episode in every world; observations() then holds the reset observations.
  void Reset();

  /// Steps every world with actions (num_envs x kActionSize, row-major, clipped to [-1, 1]).
  /// A world whose episode ends is reset at once: observations() holds its new reset
  /// observation and final_observations() the last observation of the finished episode.
  void Step(const float* actions);

  const float* observations() const { return observations_.data(); }  ///< num_envs x 186
  const float* final_observations() const {
    return final_observations_.data();
  }  ///< valid where done
  const float* rewards() const { return rewards_.data(); }
  const std::uint8_t* terminated() const { return terminated_.data(); }
  const std::uint8_t* truncated() const { return truncated_.data(); }
  /// Per world: the record of the episode that ended on the last Step, if one did.
  const std::vector<std::optional<EpisodeMetrics>>& finished_episodes() const {
    return finished_episodes_;
  }

 private:
  void StepWorld(int index, const float* action);

  int num_envs_;
  std::uint64_t seed_;
  std::vector<std::unique_ptr<Environment>> worlds_;
  std::vector<std::uint64_t> episode_counts_;
  std::unique_ptr<ThreadPool> pool_;
  std::vector<float> observations_;
  std::vector<float> final_observations_;
  std::vector<float> rewards_;
  std::vector<std::uint8_t> terminated_;
  std::vector<std::uint8_t> truncated_;
  std::vector<std::optional<EpisodeMetrics>> finished_episodes_;
};

}  // namespace colav

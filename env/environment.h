// One collision-avoidance world with a Gymnasium-style Reset/Step interface.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "env/environment_spec.h"
#include "env/scenario.h"
#include "env/world.h"

namespace colav {

/// What one step returns besides the observation (Gymnasium's reward, terminated, truncated,
/// info). `episode` is set on the step that ends the episode.
struct StepResult {
  double reward = 0.0;
  bool terminated = false;
  bool truncated = false;
  bool collision = false;
  bool goal_reached = false;
  std::optional<EpisodeMetrics> episode;
};

class Environment {
 public:
  Environment(EnvironmentConfig config, std::shared_ptr<const ScenarioSource> source);

  /// Starts the episode of scenario source->Make(seed); writes ObservationSize(config) floats.
  void Reset(std::uint64_t seed, float* observation);

  /// Advances one second under action (kActionSize values, clipped to [-1, 1]); writes the new
  /// observation (ObservationSize(config) floats). Must not be called after the episode ended
  /// without a Reset.
  StepResult Step(const double* action, float* observation);

  /// The simulated world (path, vessel, obstacles, last ranges), for traces and pictures.
  const World& world() const { return world_; }
  const EnvironmentConfig& config() const { return config_; }

 private:
  void WriteObservation(float* observation);
  /// The closeness of the current ranges, at `closeness` (kNumRays floats).
  void WriteCloseness(float* closeness) const;

  EnvironmentConfig config_;
  std::shared_ptr<const ScenarioSource> source_;
  World world_;
  std::int64_t steps_ = 0;
  double cumulative_reward_ = 0.0;
  double sum_abs_cte_ = 0.0;
  /// With a scan history: the last scan_history * scan_history_interval + 1 scans, the scan of
  /// step t in slot t modulo their number.
  std::vector<float> scan_ring_;
};

}  // namespace colav

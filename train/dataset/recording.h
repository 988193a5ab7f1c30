// Range scans recorded in the paper's training environment (TrainingScenarioGenerator) while the
// scripted pilot drives. Episode e is the scenario of seed DeriveSeed(seed, "dataset.episode", e)
// with its own pilot stream, so the scans depend on the seed alone, not on the thread count.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "env/environment_spec.h"
#include "train/dataset/pilot.h"

namespace colav {

using RangeScan = std::array<float, kNumRays>;

struct SimulatorRecordingOptions {
  ScriptedPilotOptions pilot;
  /// Steps between two recorded scans, uniform in [min, max], so consecutive scans are not
  /// near-duplicates and the sampling does not lock onto a period of the motion.
  int sample_interval_min = 5;
  int sample_interval_max = 15;
  /// At most this many scans per episode, so the data spans many scenarios.
  int max_scans_per_episode = 50;
};

/// The scans of episode `episode`: the world's ranges (m) every few steps until the episode ends.
std::vector<RangeScan> RecordEpisodeScans(std::uint64_t seed, std::uint64_t episode,
                                          const SimulatorRecordingOptions& options);

/// The first `count` scans of episodes 0, 1, 2, ... in episode order, recorded on `threads`
/// threads. `recorded` counts the scans done so far (for a progress display polled by `poll`).
std::vector<RangeScan> RecordSimulatorScans(std::int64_t count, std::uint64_t seed,
                                            const SimulatorRecordingOptions& options, int threads,
                                            std::atomic<std::int64_t>& recorded,
                                            const std::function<void()>& poll);

}  // namespace colav

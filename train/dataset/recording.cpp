#include "train/dataset/recording.h"

#include <algorithm>
#include <memory>

#include "env/environment.h"
#include "env/training_scenario.h"
#include "src/error.h"
#include "src/random.h"
#include "src/threads/thread_pool.h"

namespace colav {
namespace {

int DrawSampleInterval(Rng& rng, const SimulatorRecordingOptions& options) {
  return options.sample_interval_min +
         static_cast<int>(
             UniformIndex(rng, options.sample_interval_max - options.sample_interval_min + 1));
}

RangeScan ToRangeScan(const std::array<double, kNumRays>& ranges) {
  RangeScan scan{};
  std::transform(ranges.begin(), ranges.end(), scan.begin(),
                 [](double range) { return static_cast<float>(range); });
  return scan;
}

}  // namespace

std::vector<RangeScan> RecordEpisodeScans(std::uint64_t seed, std::uint64_t episode,
                                          const SimulatorRecordingOptions& options) {
  Environment environment(EnvironmentConfig{}, std::make_shared<TrainingScenarioGenerator>());
  std::vector<float> observation(kObservationSize);
  environment.Reset(DeriveSeed(seed, "dataset.episode", episode), observation.data());
  ScriptedPilot pilot(options.pilot, MakeRng(seed, "dataset.pilot", episode));
  Rng sampling_rng = MakeRng(seed, "dataset.sampling", episode);

  std::vector<RangeScan> scans;
  int steps_to_sample = DrawSampleInterval(sampling_rng, options);
  while (static_cast<int>(scans.size()) < options.max_scans_per_episode) {
    const std::array<double, kActionSize> action = pilot.Act(environment.world());
    const StepResult result = environment.Step(action.data(), observation.data());
    if (--steps_to_sample == 0) {
      scans.push_back(ToRangeScan(environment.world().ranges()));
      steps_to_sample = DrawSampleInterval(sampling_rng, options);
    }
    if (result.terminated || result.truncated) break;
  }
  return scans;
}

std::vector<RangeScan> RecordSimulatorScans(std::int64_t count, std::uint64_t seed,
                                            const SimulatorRecordingOptions& options, int threads,
                                            std::atomic<std::int64_t>& recorded,
                                            const std::function<void()>& poll) {
  std::vector<RangeScan> scans;
  std::uint64_t next_episode = 0;
  // Rounds of episodes in parallel; a round's episodes are appended in episode order.
  while (static_cast<std::int64_t>(scans.size()) < count) {
    const int round_size = 16 * std::max(1, threads);
    std::vector<std::vector<RangeScan>> round(static_cast<std::size_t>(round_size));
    ParallelFor(
        round_size, threads,
        [&](int i) {
          round[static_cast<std::size_t>(i)] =
              RecordEpisodeScans(seed, next_episode + static_cast<std::uint64_t>(i), options);
          recorded += static_cast<std::int64_t>(round[static_cast<std::size_t>(i)].size());
        },
        poll);
    next_episode += static_cast<std::uint64_t>(round_size);
    // Sample intervals longer than the episodes would record nothing, round after round.
    if (std::all_of(round.begin(), round.end(), [](const auto& s) { return s.empty(); })) {
      throw UserError("recording: " + std::to_string(round_size) +
                      " episodes recorded no scan (recording.sample_interval_min " +
                      std::to_string(options.sample_interval_min) +
                      " steps is longer than the episodes)");
    }
    for (const std::vector<RangeScan>& episode_scans : round) {
      for (const RangeScan& scan : episode_scans) {
        if (static_cast<std::int64_t>(scans.size()) < count) scans.push_back(scan);
      }
    }
  }
  recorded = count;
  return scans;
}

}  // namespace colav

// generate_dataset's work: simulator scans under the scripted pilot, synthetic scans of the three
// groups, then augmentation and the split (augmentation.h). Everything is a function of
// the seed; the thread count only changes the speed.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "train/dataset/augmentation.h"
#include "train/dataset/file.h"
#include "train/dataset/recording.h"
#include "train/dataset/synthetic.h"

namespace colav {

struct DatasetGenerationOptions {
  std::int64_t sim_scans = 10000;
  std::int64_t synthetic_scans = 10000;
  std::uint64_t seed = 0;
  int threads = 2;
  /// Shares of the synthetic scans: 3 circles + 2 vessels, 5 vessels; 5 circles get the rest
  /// (5,000 : 2,500 : 2,500 in the paper).
  double mixed_share = 0.5;
  double vessels_share = 0.25;
  SimulatorRecordingOptions simulator;
  SyntheticSceneOptions synthetic;
  AugmentationOptions augmentation;
};

/// Number of synthetic scans of each synthetic group (kSyntheticGroups order) for `total` scans.
std::vector<std::int64_t> SyntheticGroupSizes(std::int64_t total,
                                              const DatasetGenerationOptions& options);

/// Synthetic scans of one group; scan j of the group is drawn from its own stream
/// (seed, "dataset.synthetic.<group>", j). `done` counts finished scans.
std::vector<RangeScan> GenerateSyntheticScans(ScanGroup group, std::int64_t count,
                                              const DatasetGenerationOptions& options,
                                              std::atomic<std::int64_t>& done,
                                              const std::function<void()>& poll);

/// The whole dataset (without its config text, which the caller sets). `progress(done)` is called
/// from the calling thread with the number of source scans finished, out of sim + synthetic.
ScanDataset GenerateScanDataset(const DatasetGenerationOptions& options,
                                const std::function<void(std::int64_t done)>& progress);

}  // namespace colav

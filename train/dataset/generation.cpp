#include "train/dataset/generation.h"

#include <cmath>
#include <string>

#include "src/threads/thread_pool.h"

namespace colav {

std::vector<std::int64_t> SyntheticGroupSizes(std::int64_t total,
                                              const DatasetGenerationOptions& options) {
  const auto mixed = static_cast<std::int64_t>(std::llround(options.mixed_share * total));
  const auto vessels = static_cast<std::int64_t>(std::llround(options.vessels_share * total));
  return {mixed, vessels, total - mixed - vessels};
}

std::vector<RangeScan> GenerateSyntheticScans(ScanGroup group, std::int64_t count,
                                              const DatasetGenerationOptions& options,
                                              std::atomic<std::int64_t>& done,
                                              const std::function<void()>& poll) {
  const std::string stream = "dataset.synthetic." + std::to_string(static_cast<int>(group));
  std::vector<RangeScan> scans(static_cast<std::size_t>(count));
  ParallelFor(
      static_cast<int>(count), options.threads,
      [&](int j) {
        Rng rng = MakeRng(options.seed, stream, static_cast<std::uint64_t>(j));
        scans[static_cast<std::size_t>(j)] = ScanSyntheticScene(
            SampleSyntheticScene(rng, ObstacleCountsOf(group), options.synthetic));
        ++done;
      },
      poll);
  return scans;
}

ScanDataset GenerateScanDataset(const DatasetGenerationOptions& options,
                                const std::function<void(std::int64_t done)>& progress) {
  std::atomic<std::int64_t> recorded{0};
  std::atomic<std::int64_t> synthesised{0};
  const auto poll = [&] { progress(recorded + synthesised); };

  std::vector<RangeScan> scans = RecordSimulatorScans(
      options.sim_scans, options.seed, options.simulator, options.threads, recorded, poll);
  std::vector<ScanGroup> groups(scans.size(), ScanGroup::kSimulator);
  const std::vector<std::int64_t> sizes = SyntheticGroupSizes(options.synthetic_scans, options);
  for (std::size_t g = 0; g < kSyntheticGroups.size(); ++g) {
    const std::vector<RangeScan> synthetic =
        GenerateSyntheticScans(kSyntheticGroups[g], sizes[g], options, synthesised, poll);
    scans.insert(scans.end(), synthetic.begin(), synthetic.end());
    groups.insert(groups.end(), synthetic.size(), kSyntheticGroups[g]);
  }
  ScanDataset dataset = AugmentAndSplit(scans, groups, options.augmentation, options.seed);
  dataset.seed = static_cast<std::int64_t>(options.seed);
  return dataset;
}

}  // namespace colav

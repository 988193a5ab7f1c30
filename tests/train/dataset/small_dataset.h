// A small scan dataset (20 simulator and 40 synthetic source scans, 180 rows) for the dataset and
// VAE-data tests.
#pragma once

#include <cstdint>

#include "train/dataset/generation.h"

namespace colav::testing_util {

inline ScanDataset SmallScanDataset(std::uint64_t seed) {
  DatasetGenerationOptions options;
  options.sim_scans = 20;
  options.synthetic_scans = 40;
  options.seed = seed;
  return GenerateScanDataset(options, [](std::int64_t) {});
}

}  // namespace colav::testing_util

// The VAE dataset file (HDF5), readable by h5py and h5dump. Datasets, one row per scan:
//   ranges       float32 [N, 180]  ranges in metres, 150 = no return
//   group        int64   [N]       0 simulator, 1 synthetic 3 circles + 2 vessels,
//                                  2 synthetic 5 vessels, 3 synthetic 5 circles
//   source_scan  int64   [N]       id of the recorded or synthetic scan the row comes from
//   shift        int64   [N]       circular shift (rays) applied to that scan: row[i] =
//                                  source[(i - shift) mod 180], as numpy.roll(source, shift)
//   split        int64   [N]       0 train, 1 validation, 2 test
// File attributes: config (YAML of the generation settings), seed, description.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace colav {

enum class DatasetSplit : std::int64_t { kTrain = 0, kValidation = 1, kTest = 2 };

struct ScanDataset {
  std::vector<float> ranges;  ///< rows * 180, row-major
  std::vector<std::int64_t> group;
  std::vector<std::int64_t> source_scan;
  std::vector<std::int64_t> shift;
  std::vector<std::int64_t> split;
  std::string config;  ///< YAML
  std::int64_t seed = 0;

  std::size_t rows() const { return group.size(); }
};

/// Writes the dataset atomically (parent folders created).
void WriteScanDataset(const ScanDataset& dataset, const std::filesystem::path& path);

/// Reads and checks a dataset file: a missing file, dataset or attribute, a wrong shape, a
/// truncated file, an out-of-range group or split value or a range that is not in [0, 150] m (NaN,
/// negative) is a one-line UserError naming the file and the dataset.
ScanDataset ReadScanDataset(const std::filesystem::path& path);

}  // namespace colav

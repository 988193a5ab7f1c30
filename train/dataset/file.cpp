#include "train/dataset/file.h"

#include <fmt/format.h>

#include "env/environment_spec.h"
#include "env/range_finder.h"
#include "src/error.h"
#include "src/hdf5_io.h"
#include "train/dataset/scan_group.h"

namespace colav {
namespace {

constexpr char kDescription[] =
    "Range scans for VAE pre-training (colav-vae generate_dataset). ranges: float32 [N, 180], "
    "metres, 150 = no return; simulator rays at -pi + (i+1)*2 deg from the heading, synthetic rays "
    "at -pi/2 + i*2 deg from +x. group: 0 simulator, 1 synthetic 3 circles + 2 vessels, "
    "2 synthetic 5 vessels, 3 synthetic 5 circles. source_scan: id of the original scan. "
    "shift: row = numpy.roll(original, shift). split: 0 train, 1 validation, 2 test (by source "
    "scan).";

void CheckLength(const Hdf5File& file, const std::string& name, std::size_t length,
                 std::size_t rows) {
  if (length != rows) {
    throw UserError(file.path().string() + ": dataset '" + name + "' has " +
                    std::to_string(length) + " rows, 'ranges' has " + std::to_string(rows));
  }
}

void CheckRange(const Hdf5File& file, const std::string& name,
                const std::vector<std::int64_t>& values, std::int64_t max) {
  for (const std::int64_t value : values) {
    if (value < 0 || value > max) {
      throw UserError(file.path().string() + ": dataset '" + name + "' holds " +
                      std::to_string(value) + ", expected 0.." + std::to_string(max));
    }
  }
}

// Every range is a finite distance the range-finder can measure: a NaN or a negative value (a
// hand-edited or foreign file) would train a VAE on nonsense without any error.
void CheckRanges(const Hdf5File& file, const std::vector<float>& ranges) {
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    const float range = ranges[k];
    if (!(range >= 0.0F && range <= static_cast<float>(RangeFinder::kRange))) {
      throw UserError(fmt::format("{}: dataset 'ranges' row {} ray {} holds {}, expected 0..{:g}",
                                  file.path().string(), k / kNumRays, k % kNumRays, range,
                                  RangeFinder::kRange));
    }
  }
}

}  // namespace

void WriteScanDataset(const ScanDataset& dataset, const std::filesystem::path& path) {
  Hdf5File::CreateAtomically(path, [&](Hdf5File& file) {
    file.WriteFloatMatrix("ranges", dataset.ranges, dataset.rows(), kNumRays);
    file.WriteIntVector("group", dataset.group);
    file.WriteIntVector("source_scan", dataset.source_scan);
    file.WriteIntVector("shift", dataset.shift);
    file.WriteIntVector("split", dataset.split);
    file.SetAttribute("config", dataset.config);
    file.SetAttribute("seed", dataset.seed);
    file.SetAttribute("description", kDescription);
  });
}

ScanDataset ReadScanDataset(const std::filesystem::path& path) {
  const Hdf5File file = Hdf5File::Open(path);
  ScanDataset dataset;
  FloatMatrix ranges = file.ReadFloatMatrix("ranges", kNumRays);
  dataset.ranges = std::move(ranges.data);
  dataset.group = file.ReadIntVector("group");
  dataset.source_scan = file.ReadIntVector("source_scan");
  dataset.shift = file.ReadIntVector("shift");
  dataset.split = file.ReadIntVector("split");
  CheckLength(file, "group", dataset.group.size(), ranges.rows);
  CheckLength(file, "source_scan", dataset.source_scan.size(), ranges.rows);
  CheckLength(file, "shift", dataset.shift.size(), ranges.rows);
  CheckLength(file, "split", dataset.split.size(), ranges.rows);
  CheckRanges(file, dataset.ranges);
  CheckRange(file, "group", dataset.group, kNumScanGroups - 1);
  CheckRange(file, "shift", dataset.shift, kNumRays - 1);
  CheckRange(file, "split", dataset.split, static_cast<std::int64_t>(DatasetSplit::kTest));
  dataset.config = file.GetStringAttribute("config");
  dataset.seed = file.GetIntAttribute("seed");
  return dataset;
}

}  // namespace colav

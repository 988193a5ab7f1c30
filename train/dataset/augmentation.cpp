#include "train/dataset/augmentation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "src/random.h"

namespace colav {

std::vector<DatasetSplit> SplitSourceScans(std::int64_t count, const AugmentationOptions& options,
                                           Rng& rng) {
  std::vector<std::int64_t> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), 0);
  for (std::int64_t i = count - 1; i > 0; --i) {  // Fisher-Yates
    std::swap(order[static_cast<std::size_t>(i)],
              order[UniformIndex(rng, static_cast<std::uint64_t>(i + 1))]);
  }
  const auto test_count = static_cast<std::int64_t>(std::llround(options.test_fraction * count));
  const auto validation_count = static_cast<std::int64_t>(
      std::llround(options.validation_fraction * static_cast<double>(count - test_count)));
  std::vector<DatasetSplit> split(static_cast<std::size_t>(count), DatasetSplit::kTrain);
  for (std::int64_t k = 0; k < test_count + validation_count; ++k) {
    split[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])] =
        k < test_count ? DatasetSplit::kTest : DatasetSplit::kValidation;
  }
  return split;
}

std::vector<std::int64_t> DrawShifts(int count, Rng& rng) {
  if (count < 0 || count >= kNumRays) throw std::invalid_argument("DrawShifts: bad count");
  std::vector<std::int64_t> shifts;
  while (static_cast<int>(shifts.size()) < count) {
    const auto shift = static_cast<std::int64_t>(1 + UniformIndex(rng, kNumRays - 1));
    if (std::find(shifts.begin(), shifts.end(), shift) == shifts.end()) shifts.push_back(shift);
  }
  return shifts;
}

std::vector<std::int64_t> ShiftsOfScan(const AugmentationOptions& options, Rng& rng) {
  if (options.fixed_shift_rays == 0) return DrawShifts(options.shifts_per_scan, rng);
  if (options.shifts_per_scan > 2 || options.fixed_shift_rays < 0 ||
      2 * options.fixed_shift_rays >= kNumRays) {
    throw std::invalid_argument("ShiftsOfScan: bad fixed shifts");
  }
  const std::vector<std::int64_t> fixed = {options.fixed_shift_rays,
                                           kNumRays - options.fixed_shift_rays};
  return {fixed.begin(), fixed.begin() + options.shifts_per_scan};
}

RangeScan RollScan(const RangeScan& scan, std::int64_t shift) {
  RangeScan rolled{};
  for (std::int64_t i = 0; i < kNumRays; ++i) {
    rolled[static_cast<std::size_t>((i + shift) % kNumRays)] = scan[static_cast<std::size_t>(i)];
  }
  return rolled;
}

ScanDataset AugmentAndSplit(const std::vector<RangeScan>& scans,
                            const std::vector<ScanGroup>& groups,
                            const AugmentationOptions& options, std::uint64_t seed) {
  if (scans.size() != groups.size()) throw std::invalid_argument("AugmentAndSplit: sizes differ");
  Rng split_rng = MakeRng(seed, "dataset.split");
  const std::vector<DatasetSplit> split =
      SplitSourceScans(static_cast<std::int64_t>(scans.size()), options, split_rng);
  Rng shift_rng = MakeRng(seed, "dataset.shifts");
  ScanDataset dataset;
  const std::size_t rows = scans.size() * static_cast<std::size_t>(1 + options.shifts_per_scan);
  dataset.ranges.reserve(rows * kNumRays);
  for (std::size_t s = 0; s < scans.size(); ++s) {
    std::vector<std::int64_t> shifts = {0};
    for (const std::int64_t shift : ShiftsOfScan(options, shift_rng)) {
      shifts.push_back(shift);
    }
    for (const std::int64_t shift : shifts) {
      const RangeScan row = RollScan(scans[s], shift);
      dataset.ranges.insert(dataset.ranges.end(), row.begin(), row.end());
      dataset.group.push_back(static_cast<std::int64_t>(groups[s]));
      dataset.source_scan.push_back(static_cast<std::int64_t>(s));
      dataset.shift.push_back(shift);
      dataset.split.push_back(static_cast<std::int64_t>(split[s]));
    }
  }
  return dataset;
}

}  // namespace colav

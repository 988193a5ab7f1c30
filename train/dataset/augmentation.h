// From source scans to the stored dataset (paper, "Data generation and augmentation"; spec
// README): each scan plus random circular shifts of it (rotations about the vessel's z-axis), or
// the reference code's two fixed shifts of +-10 rays (+-20 degrees, reference-learning.md 4.2),
// split train:test by source scan, so no rotation of a test scan is ever trained on, and a part of
// the training scans held out for validation.
#pragma once

#include <cstdint>
#include <vector>

#include "src/seeding.h"
#include "train/dataset/file.h"
#include "train/dataset/recording.h"
#include "train/dataset/scan_group.h"

namespace colav {

struct AugmentationOptions {
  int shifts_per_scan = 2;  ///< shifts added to each scan (N -> (1 + shifts) N)
  /// 0: the shifts are random. k > 0: they are +k then -k rays (the first `shifts_per_scan` of
  /// the two), as the reference code's rolls by +-10 (reference-learning.md 4.2 step 2).
  int fixed_shift_rays = 0;
  double test_fraction = 0.3;        ///< of the source scans
  double validation_fraction = 0.2;  ///< of the non-test source scans
};

/// Split of each of `count` source scans: a seeded shuffle, the first round(test_fraction * count)
/// to test, then round(validation_fraction * rest) to validation, the others to train.
std::vector<DatasetSplit> SplitSourceScans(std::int64_t count, const AugmentationOptions& options,
                                           Rng& rng);

/// `count` distinct shifts in 1..179 (a shift of 0 would duplicate the original).
std::vector<std::int64_t> DrawShifts(int count, Rng& rng);

/// The shifts of one source scan: drawn, or the fixed ones (-k stored as 180 - k, mod 180).
std::vector<std::int64_t> ShiftsOfScan(const AugmentationOptions& options, Rng& rng);

/// row[i] = scan[(i - shift) mod 180], numpy.roll's convention.
RangeScan RollScan(const RangeScan& scan, std::int64_t shift);

/// The dataset rows: for each source scan in order, the original then its shifts. Rows of one
/// source scan share its split. Shifts and split are drawn from streams of `seed`.
ScanDataset AugmentAndSplit(const std::vector<RangeScan>& scans,
                            const std::vector<ScanGroup>& groups,
                            const AugmentationOptions& options, std::uint64_t seed);

}  // namespace colav

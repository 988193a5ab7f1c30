#include "train/dataset/generation.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "train/dataset/augmentation.h"

namespace colav {
namespace {

DatasetGenerationOptions SmallOptions(std::uint64_t seed, int threads) {
  DatasetGenerationOptions options;
  options.sim_scans = 40;
  options.synthetic_scans = 40;
  options.seed = seed;
  options.threads = threads;
  return options;
}

ScanDataset Generate(const DatasetGenerationOptions& options) {
  return GenerateScanDataset(options, [](std::int64_t) {});
}

TEST(DatasetGenerationTest, ShapesAndGroupCounts) {
  const ScanDataset dataset = Generate(SmallOptions(3, 2));
  ASSERT_EQ(dataset.rows(), 240U);  // (40 + 40) scans x (original + 2 shifts)
  EXPECT_EQ(dataset.ranges.size(), 240U * kNumRays);
  EXPECT_EQ(dataset.source_scan.size(), 240U);
  EXPECT_EQ(dataset.shift.size(), 240U);
  EXPECT_EQ(dataset.split.size(), 240U);
  std::map<std::int64_t, int> rows_per_group;
  for (const std::int64_t group : dataset.group) ++rows_per_group[group];
  EXPECT_EQ(rows_per_group[0], 120);  // simulator
  EXPECT_EQ(rows_per_group[1], 60);   // 50 %: 3 circles + 2 vessels
  EXPECT_EQ(rows_per_group[2], 30);   // 25 %: 5 vessels
  EXPECT_EQ(rows_per_group[3], 30);   // 25 %: 5 circles
  for (const float range : dataset.ranges) {
    EXPECT_GE(range, 0.0F);
    EXPECT_LE(range, 150.0F);
  }
  // The simulator sees obstacles (not only empty scans).
  int seen = 0;
  for (std::size_t row = 0; row < dataset.rows(); ++row) {
    if (dataset.group[row] != 0) continue;
    for (int i = 0; i < kNumRays; ++i) seen += dataset.ranges[row * kNumRays + i] < 150.0F;
  }
  EXPECT_GT(seen, 0);
}

TEST(DatasetGenerationTest, SplitIsBySourceScanWithTheRequestedShares) {
  const ScanDataset dataset = Generate(SmallOptions(4, 2));
  std::map<std::int64_t, std::set<std::int64_t>> splits_of_source;
  std::map<std::int64_t, int> sources_per_split;
  for (std::size_t row = 0; row < dataset.rows(); ++row) {
    splits_of_source[dataset.source_scan[row]].insert(dataset.split[row]);
  }
  ASSERT_EQ(splits_of_source.size(), 80U);
  for (const auto& [source, splits] : splits_of_source) {
    EXPECT_EQ(splits.size(), 1U) << "source scan " << source << " is in several splits";
    ++sources_per_split[*splits.begin()];
  }
  EXPECT_EQ(sources_per_split[2], 24);  // round(0.3 * 80) test
  EXPECT_EQ(sources_per_split[1], 11);  // round(0.2 * 56) validation
  EXPECT_EQ(sources_per_split[0], 45);
}

TEST(DatasetGenerationTest, RowsAreShiftedCopiesOfTheirSource) {
  const ScanDataset dataset = Generate(SmallOptions(5, 2));
  for (std::size_t row = 0; row < dataset.rows(); row += 3) {
    ASSERT_EQ(dataset.shift[row], 0);
    RangeScan original{};
    std::copy_n(dataset.ranges.begin() + static_cast<std::ptrdiff_t>(row * kNumRays), kNumRays,
                original.begin());
    std::set<std::int64_t> shifts;
    for (std::size_t k = 1; k < 3; ++k) {
      EXPECT_EQ(dataset.source_scan[row + k], dataset.source_scan[row]);
      const std::int64_t shift = dataset.shift[row + k];
      EXPECT_GE(shift, 1);
      EXPECT_LE(shift, 179);
      shifts.insert(shift);
      const RangeScan rolled = RollScan(original, shift);
      for (int i = 0; i < kNumRays; ++i) {
        ASSERT_EQ(dataset.ranges[(row + k) * kNumRays + i], rolled[static_cast<std::size_t>(i)]);
      }
    }
    EXPECT_EQ(shifts.size(), 2U);
  }
}

// The reference code's augmentation (reference-learning.md 4.2 step 2): each scan rolled by +10
// and by -10 rays, numpy.roll(x, 10) and numpy.roll(x, -10); the sources and their split do not
// change.
TEST(DatasetGenerationTest, FixedShiftsAreTheReferenceRolls) {
  DatasetGenerationOptions options = SmallOptions(5, 2);
  const ScanDataset random_shifts = Generate(options);
  options.augmentation.fixed_shift_rays = 10;
  const ScanDataset fixed = Generate(options);
  ASSERT_EQ(fixed.rows(), random_shifts.rows());
  EXPECT_EQ(fixed.split, random_shifts.split);
  EXPECT_EQ(fixed.source_scan, random_shifts.source_scan);
  for (std::size_t row = 0; row < fixed.rows(); row += 3) {
    ASSERT_EQ(fixed.shift[row], 0);
    ASSERT_EQ(fixed.shift[row + 1], 10);
    ASSERT_EQ(fixed.shift[row + 2], 170);  // -10 mod 180
    for (std::size_t i = 0; i < kNumRays; ++i) {
      const float original = fixed.ranges[row * kNumRays + i];
      EXPECT_EQ(fixed.ranges[(row + 1) * kNumRays + (i + 10) % kNumRays], original);
      EXPECT_EQ(fixed.ranges[(row + 2) * kNumRays + (i + 170) % kNumRays], original);
    }
  }
  options.augmentation.shifts_per_scan = 1;  // +10 only
  const ScanDataset one_shift = Generate(options);
  ASSERT_EQ(one_shift.rows(), 160U);
  for (std::size_t row = 0; row < one_shift.rows(); row += 2) {
    EXPECT_EQ(one_shift.shift[row], 0);
    EXPECT_EQ(one_shift.shift[row + 1], 10);
  }
}

TEST(DatasetGenerationTest, RollFollowsNumpy) {
  RangeScan scan{};
  for (int i = 0; i < kNumRays; ++i) scan[static_cast<std::size_t>(i)] = static_cast<float>(i);
  const RangeScan rolled = RollScan(scan, 10);  // numpy.roll(x, 10)[i] = x[i - 10]
  EXPECT_EQ(rolled[10], 0.0F);
  EXPECT_EQ(rolled[0], 170.0F);
  EXPECT_EQ(rolled[179], 169.0F);
}

TEST(DatasetGenerationTest, SameSeedSameDataAnyThreadCountOtherSeedOtherData) {
  const ScanDataset one_thread = Generate(SmallOptions(9, 1));
  const ScanDataset two_threads = Generate(SmallOptions(9, 2));
  EXPECT_EQ(one_thread.ranges, two_threads.ranges);
  EXPECT_EQ(one_thread.group, two_threads.group);
  EXPECT_EQ(one_thread.source_scan, two_threads.source_scan);
  EXPECT_EQ(one_thread.shift, two_threads.shift);
  EXPECT_EQ(one_thread.split, two_threads.split);
  const ScanDataset other = Generate(SmallOptions(10, 2));
  EXPECT_NE(one_thread.ranges, other.ranges);
  EXPECT_NE(one_thread.split, other.split);
}

}  // namespace
}  // namespace colav

// Navigation normalisation against hand-computed moments (SB3's RunningMeanStd semantics).
#include "train/ppo/navigation_normalizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace colav {
namespace {

constexpr int kStride = kNavigationSize + 2;  // rows with two values that are not navigation

// Two rows: navigation value j is j and 3j in them; the extra values are 100 and 200.
std::vector<float> TwoRows() {
  std::vector<float> rows(2 * kStride);
  for (int j = 0; j < kNavigationSize; ++j) {
    rows[j] = static_cast<float>(j);
    rows[kStride + j] = static_cast<float>(3 * j);
  }
  rows[kNavigationSize] = rows[kNavigationSize + 1] = 100.0f;
  rows[kStride + kNavigationSize] = rows[kStride + kNavigationSize + 1] = 200.0f;
  return rows;
}

TEST(NavigationNormalizerTest, MomentsMergeTheRowsWithThePrior) {
  NavigationNormalizer normalizer;
  const std::vector<float> rows = TwoRows();
  normalizer.Update(rows.data(), 2, kStride);
  for (int j = 0; j < kNavigationSize; ++j) {
    // Batch of {j, 3j}: mean 2j, variance j^2; the prior is mean 0, variance 1, weight 1e-4.
    const double total = 2.0 + 1e-4;
    const double mean = 2.0 * j * 2.0 / total;
    const double variance = (1e-4 + 2.0 * j * j + 4.0 * j * j * 1e-4 * 2.0 / total) / total;
    EXPECT_NEAR(normalizer.moments()[j].mean, mean, 1e-12);
    EXPECT_NEAR(normalizer.moments()[j].variance, variance, 1e-12);
    EXPECT_DOUBLE_EQ(normalizer.moments()[j].count, total);
  }
}

TEST(NavigationNormalizerTest, NormalisesTheNavigationValuesOnly) {
  NavigationNormalizer normalizer;
  std::vector<float> rows = TwoRows();
  normalizer.Update(rows.data(), 2, kStride);
  const NavigationNormalization applied = normalizer.Normalization();
  normalizer.Normalize(rows.data(), 2, kStride);
  for (int j = 1; j < kNavigationSize; ++j) {
    const double spread = std::sqrt(normalizer.moments()[j].variance + 1e-8);
    EXPECT_FLOAT_EQ(applied.spread[j], static_cast<float>(spread));
    // The two values sit one spread below and above their mean (up to the prior's weight).
    EXPECT_NEAR(rows[j], -1.0, 1e-3);
    EXPECT_NEAR(rows[kStride + j], 1.0, 1e-3);
    EXPECT_EQ(rows[j], (static_cast<float>(j) - applied.mean[j]) / applied.spread[j]);
  }
  EXPECT_EQ(rows[0], 0.0f);  // a constant value: variance ~0, the epsilon keeps it finite
  EXPECT_EQ(rows[kNavigationSize], 100.0f);
  EXPECT_EQ(rows[kStride + kNavigationSize + 1], 200.0f);
}

TEST(NavigationNormalizerTest, RestoredMomentsNormaliseAlike) {
  NavigationNormalizer original, restored;
  std::vector<float> rows = TwoRows();
  original.Update(rows.data(), 2, kStride);
  restored.Restore(original.moments());
  std::vector<float> copy = rows;
  original.Normalize(rows.data(), 2, kStride);
  restored.Normalize(copy.data(), 2, kStride);
  EXPECT_EQ(rows, copy);
}

}  // namespace
}  // namespace colav

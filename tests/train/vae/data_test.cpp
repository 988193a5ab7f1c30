#include "train/vae/data.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/src/test_util.h"
#include "tests/train/dataset/small_dataset.h"
#include "train/dataset/file.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;

TEST(DatasetLoadingTest, SplitsTransformAndNoise) {
  const TemporaryFolder folder;
  const ScanDataset dataset = testing_util::SmallScanDataset(3);
  WriteScanDataset(dataset, folder / "data.h5");
  const VaeData linear = LoadVaeData(folder / "data.h5", ClosenessTransform::kLinear);
  const VaeData log = LoadVaeData(folder / "data.h5", ClosenessTransform::kLog);
  EXPECT_EQ(linear.train.size(0) + linear.validation.size(0) + linear.test.size(0), 180);
  EXPECT_EQ(linear.test.size(0), 54);  // round(0.3 * 60) source scans x 3
  EXPECT_EQ(linear.test_group.size(0), 54);
  EXPECT_EQ(linear.train.size(1), kNumRays);

  // The first train row is the first row of the file whose split is train.
  std::size_t first_train = 0;
  while (dataset.split[first_train] != 0) ++first_train;
  for (int i = 0; i < kNumRays; ++i) {
    const double range = dataset.ranges[first_train * kNumRays + i];
    EXPECT_NEAR(linear.train[0][i].item<double>(), 1.0 - range / 150.0, 1e-6);
    EXPECT_NEAR(log.train[0][i].item<double>(), 1.0 - std::log1p(range) / std::log(151.0), 1e-6);
  }
  EXPECT_GE(linear.train.min().item<double>(), 0.0);
  EXPECT_LE(linear.train.max().item<double>(), 1.0);

  const torch::Tensor big = torch::zeros({400, kNumRays});
  const torch::Tensor noisy = WithTrainingNoise(big, 0.007, 11);
  EXPECT_NEAR(noisy.std().item<double>(), std::sqrt(0.007), 0.002);
  EXPECT_TRUE(torch::equal(noisy, WithTrainingNoise(big, 0.007, 11)));
  EXPECT_FALSE(torch::equal(noisy, WithTrainingNoise(big, 0.007, 12)));
  EXPECT_TRUE(torch::equal(WithTrainingNoise(big, 0.0, 11), big));
  // Clipped: the unclipped draw pushed into [0, 1].
  EXPECT_LT(noisy.min().item<double>(), 0.0);
  const torch::Tensor clipped = WithTrainingNoise(big, 0.007, 11, /*clip=*/true);
  EXPECT_TRUE(torch::equal(clipped, noisy.clamp(0.0, 1.0)));
}

}  // namespace
}  // namespace colav

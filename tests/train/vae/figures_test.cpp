#include "train/vae/figures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "env/range_finder.h"
#include "train/vae/latent_density.h"

namespace colav {
namespace {

TEST(VaeFiguresTest, KdeOfAStandardNormalIsANormalDensity) {
  torch::manual_seed(0);
  const torch::Tensor points = torch::randn({4000, 2}, torch::kDouble);
  const DensityGrid grid = GaussianKde2d(points, 80);
  ASSERT_EQ(grid.density.sizes(), (std::vector<std::int64_t>{80, 80}));
  const double dx = (grid.x[1] - grid.x[0]).item<double>();
  const double dy = (grid.y[1] - grid.y[0]).item<double>();
  // The grid covers the central 99 % plus a margin: nearly all the mass.
  EXPECT_NEAR(grid.density.sum().item<double>() * dx * dy, 1.0, 0.02);
  // Peak of N(0, (1 + h^2) I) with Scott's h = n^(-1/6) = 0.25: 1 / (2 pi 1.0625) = 0.1498.
  EXPECT_NEAR(grid.density.max().item<double>(), 0.1498, 0.015);
}

TEST(VaeFiguresTest, RangesInvertTheClosenessTransforms) {
  const torch::Tensor ranges = torch::tensor({0.0, 12.5, 75.0, 150.0}, torch::kDouble);
  for (const ClosenessTransform transform :
       {ClosenessTransform::kLinear, ClosenessTransform::kLog}) {
    std::vector<double> closeness;
    for (int i = 0; i < 4; ++i) closeness.push_back(Closeness(ranges[i].item<double>(), transform));
    EXPECT_TRUE(
        torch::allclose(RangesFromCloseness(torch::tensor(closeness, torch::kDouble), transform),
                        ranges, 1e-9, 1e-9));
  }
}

TEST(VaeFiguresTest, PickScansFindsObstaclesAcrossTheSeam) {
  torch::Tensor scans = torch::zeros({50, kNumRays});
  scans[3][0] = 0.5;     // seam
  scans[7][90] = 0.5;    // ahead only
  scans[11][178] = 0.5;  // seam
  const std::vector<std::int64_t> near_seam = PickScans(scans, 5, 1, true);
  ASSERT_EQ(near_seam.size(), 2U);
  EXPECT_EQ(std::set<std::int64_t>(near_seam.begin(), near_seam.end()),
            (std::set<std::int64_t>{3, 11}));
  EXPECT_EQ(PickScans(scans, 5, 1, false).size(), 3U);
}

}  // namespace
}  // namespace colav

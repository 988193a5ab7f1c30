// The paper's latent-density figure: a 2-D Gaussian kernel density estimate of the test set's
// latent codes (latent size 2), one heat-map panel per model (Shallow / Deep x beta 0, 1, 5).
#pragma once

#include <torch/torch.h>

#include <filesystem>
#include <string>
#include <vector>

namespace colav {

struct DensityGrid {
  torch::Tensor x;        ///< [nx] grid abscissae
  torch::Tensor y;        ///< [ny] grid ordinates
  torch::Tensor density;  ///< [ny, nx]
};

/// Gaussian KDE of points [n, 2] on a size x size grid covering the central 99 % of the points
/// (plus a margin). Bandwidth: Scott's rule with the full covariance, as scipy's gaussian_kde.
DensityGrid GaussianKde2d(const torch::Tensor& points, int size = 100);

struct DensityPanel {
  std::string title;
  DensityGrid grid;
};

/// Panels in a grid of `columns` columns, each a heat map of the density.
void DrawDensityPanels(const std::vector<DensityPanel>& panels, int columns,
                       const std::string& title, const std::filesystem::path& png);

}  // namespace colav

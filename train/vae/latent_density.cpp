#include "train/vae/latent_density.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "env/angles.h"
#include "src/figures/gnuplot.h"
#include "src/figures/style.h"

namespace colav {
namespace {

// Grid points per chunk of the density sum, to bound the [chunk, n] distance matrix.
constexpr std::int64_t kGridChunk = 512;

// White (no density) to dark blue.
constexpr const char* kDensityPalette =
    "(0 '#ffffff', 0.15 '#c6dbef', 0.4 '#6baed6', 0.7 '#2171b5', 1 '#08306b')";

torch::Tensor Axis(const torch::Tensor& values, int size) {
  const double low = torch::quantile(values, 0.005).item<double>();
  const double high = torch::quantile(values, 0.995).item<double>();
  const double margin = 0.15 * std::max(high - low, 1e-3);
  return torch::linspace(low - margin, high + margin, size, torch::kDouble);
}

}  // namespace

DensityGrid GaussianKde2d(const torch::Tensor& points, int size) {
  if (points.dim() != 2 || points.size(1) != 2 || points.size(0) < 3) {
    throw std::invalid_argument("GaussianKde2d: points must be [n >= 3, 2]");
  }
  const torch::NoGradGuard no_grad;
  const torch::Tensor p = points.to(torch::kDouble);
  const auto n = static_cast<double>(p.size(0));
  const torch::Tensor centred = p - p.mean(0);
  // Kernel covariance H = cov * n^(-2/6); a tiny ridge keeps a degenerate (collapsed) latent
  // drawable.
  const torch::Tensor covariance = centred.t().mm(centred) / (n - 1.0) * std::pow(n, -1.0 / 3.0) +
                                   1e-9 * torch::eye(2, torch::kDouble);
  const torch::Tensor cholesky = torch::linalg_cholesky(covariance);
  const torch::Tensor whitening = torch::linalg_inv(cholesky).t();  // row vectors: v W
  const double normaliser = 1.0 / (2.0 * kPi * cholesky.diagonal().prod().item<double>() * n);

  DensityGrid grid;
  grid.x = Axis(p.select(1, 0), size);
  grid.y = Axis(p.select(1, 1), size);
  const std::vector<torch::Tensor> mesh = torch::meshgrid({grid.y, grid.x}, "ij");
  const torch::Tensor grid_points = torch::stack({mesh[1].flatten(), mesh[0].flatten()}, 1);
  const torch::Tensor white_points = p.mm(whitening);
  const torch::Tensor white_grid = grid_points.mm(whitening);
  std::vector<torch::Tensor> chunks;
  for (std::int64_t start = 0; start < white_grid.size(0); start += kGridChunk) {
    const torch::Tensor chunk =
        white_grid.narrow(0, start, std::min(kGridChunk, white_grid.size(0) - start));
    chunks.push_back(torch::exp(-0.5 * torch::cdist(chunk, white_points).square()).sum(1));
  }
  grid.density = (torch::cat(chunks) * normaliser).view({size, size});
  return grid;
}

void DrawDensityPanels(const std::vector<DensityPanel>& panels, int columns,
                       const std::string& title, const std::filesystem::path& png) {
  const int rows = static_cast<int>((panels.size() + columns - 1) / columns);
  std::ostringstream script;
  script << MultiplotLayout(rows, columns, title, 14)
         << "set size square\nunset key\nset xlabel 'z_1'\nset ylabel 'z_2'\n"
         << "set palette defined " << kDensityPalette << "\n"
         << "unset colorbox\nset tics out nomirror\n";
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const DensityGrid& grid = panels[k].grid;
    const auto x = grid.x.accessor<double, 1>();
    const auto y = grid.y.accessor<double, 1>();
    const auto d = grid.density.accessor<double, 2>();
    script << "$kde" << k << " << EOD\n";
    for (std::int64_t j = 0; j < grid.y.size(0); ++j) {
      for (std::int64_t i = 0; i < grid.x.size(0); ++i) {
        script << x[i] << ' ' << y[j] << ' ' << d[j][i] << '\n';
      }
      script << '\n';
    }
    script << "EOD\n"
           << "set title " << GnuplotQuote(panels[k].title) << "\n"
           << "set xrange [" << x[0] << ":" << x[grid.x.size(0) - 1] << "]\n"
           << "set yrange [" << y[0] << ":" << y[grid.y.size(0) - 1] << "]\n"
           << "plot $kde" << k << " using 1:2:3 with image\n";
  }
  script << "unset multiplot\n";
  RenderGnuplotPng(script.str(), png, 420 * columns, 420 * rows + 40);
}

}  // namespace colav

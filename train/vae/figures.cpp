#include "train/vae/figures.h"

#include <ATen/CPUGeneratorImpl.h>

#include <cmath>
#include <sstream>

#include "env/angles.h"
#include "env/range_finder.h"
#include "src/figures/gnuplot.h"
#include "src/figures/style.h"

namespace colav {
namespace {

constexpr int kPanelSize = 330;  // pixels per polar panel

// The paper's blue and red: input scans and their reconstructions, train and validation losses.
constexpr const char* kBlue = "#1f4fd0";
constexpr const char* kRed = "#e02020";

constexpr const char* kPolarGridColour = "#d0d0d0";
constexpr const char* kSeamColour = "#808080";

// Inline gnuplot data block `name`: one "bearing range" line per ray, heading up, closed loop.
std::string PolarDataBlock(const std::string& name, const torch::Tensor& ranges) {
  std::ostringstream block;
  block << "$" << name << " << EOD\n";
  const auto values = ranges.accessor<float, 1>();
  for (int k = 0; k <= kNumRays; ++k) {
    const int i = k % kNumRays;
    const double bearing =
        kPi / 2.0 + RangeFinder::kVesselFirstRayAngle + i * RangeFinder::kRaySpacing;
    block << bearing << ' ' << values[i] << '\n';
  }
  block << "EOD\n";
  return block.str();
}

std::string PolarPanelSettings() {
  return "set polar\nset angles radians\nset size ratio -1\nunset border\nunset xtics\n"
         "unset ytics\nunset raxis\nunset key\nset rrange [0:150]\nset xrange [-150:150]\n"
         "set yrange [-150:150]\nset grid polar pi/6 " +
         LineColour(kPolarGridColour) + "\nset rtics 50 format ''\n" +
         // The seam between ray 179 and ray 0, straight behind the vessel.
         "set arrow 1 from 0,0 to 0,-150 nohead dt 2 " + LineColour(kSeamColour) + "\n" +
         "set object 1 circle at 0,0 size 3 fc rgb 'black' fs solid\n";
}

}  // namespace

torch::Tensor RangesFromCloseness(const torch::Tensor& closeness, ClosenessTransform transform) {
  const torch::Tensor x = closeness.clamp(0.0, 1.0);
  if (transform == ClosenessTransform::kLog) {
    return torch::exp((1.0 - x) * std::log(RangeFinder::kRange + 1.0)) - 1.0;
  }
  return RangeFinder::kRange * (1.0 - x);
}

torch::Tensor MeanReconstruction(ConvVae& model, const torch::Tensor& x) {
  const torch::NoGradGuard no_grad;
  return model->decoder()->forward(model->encoder()->Mu(x));
}

std::vector<std::int64_t> PickScans(const torch::Tensor& scans, std::int64_t count,
                                    std::uint64_t seed, bool near_seam, std::int64_t seam_rays) {
  torch::Tensor seen = scans;
  if (near_seam) {
    seen = torch::cat(
        {scans.narrow(1, 0, seam_rays), scans.narrow(1, kNumRays - seam_rays, seam_rays)}, 1);
  }
  const torch::Tensor eligible = seen.amax(1).gt(0.05);
  torch::Generator generator = at::make_generator<at::CPUGeneratorImpl>(seed);
  const torch::Tensor order = torch::randperm(scans.size(0), generator, torch::kLong);
  std::vector<std::int64_t> picked;
  const auto order_values = order.accessor<std::int64_t, 1>();
  const auto eligible_values = eligible.accessor<bool, 1>();
  for (std::int64_t k = 0; k < order.size(0) && static_cast<std::int64_t>(picked.size()) < count;
       ++k) {
    if (eligible_values[order_values[k]]) picked.push_back(order_values[k]);
  }
  return picked;
}

void DrawPolarReconstructions(const torch::Tensor& scans, const std::vector<ConvVae>& models,
                              const std::vector<std::string>& model_names,
                              ClosenessTransform transform, const std::string& title,
                              const std::filesystem::path& png) {
  const std::int64_t columns = scans.size(0);
  const auto rows = static_cast<std::int64_t>(models.size());
  const torch::Tensor inputs = RangesFromCloseness(scans, transform).to(torch::kFloat32);
  std::ostringstream script;
  script << MultiplotLayout(rows, columns, title + "   (blue: input, red: reconstruction)", 13)
         << PolarPanelSettings();
  for (std::int64_t m = 0; m < rows; ++m) {
    ConvVae model = models[static_cast<std::size_t>(m)];  // a handle on the same module
    const torch::Tensor reconstructions =
        RangesFromCloseness(MeanReconstruction(model, scans), transform).to(torch::kFloat32);
    for (std::int64_t s = 0; s < columns; ++s) {
      script << PolarDataBlock("in", inputs[s].contiguous())
             << PolarDataBlock("out", reconstructions[s].contiguous()) << "set title "
             << GnuplotQuote(model_names[static_cast<std::size_t>(m)]) << "\n"
             << "plot $in using 1:2 with lines lw 2 " << LineColour(kBlue)
             << ", $out using 1:2 with lines lw 2 " << LineColour(kRed) << "\n";
    }
  }
  script << "unset multiplot\n";
  RenderGnuplotPng(script.str(), png, static_cast<int>(columns) * kPanelSize,
                   static_cast<int>(rows) * kPanelSize + 40);
}

void DrawTrainingCurves(const std::vector<std::vector<EpochLosses>>& histories, double beta,
                        const std::string& title, const std::filesystem::path& png) {
  std::ostringstream script;
  std::ostringstream plots;
  for (std::size_t s = 0; s < histories.size(); ++s) {
    script << "$seed" << s << " << EOD\n";
    for (const EpochLosses& h : histories[s]) {
      script << h.epoch << ' ' << h.train_bce + beta * h.train_kl << ' '
             << h.validation_bce + beta * h.validation_kl << '\n';
    }
    script << "EOD\n";
    plots << (s == 0 ? "plot " : ", ") << "$seed" << s << " using 1:2 with lines lw 2 "
          << LineColour(kBlue) << " title " << (s == 0 ? "'train (noisy)'" : "''") << ", $seed" << s
          << " using 1:3 with lines lw 2 dt 2 " << LineColour(kRed) << " title "
          << (s == 0 ? "'validation'" : "''");
  }
  script << "set title " << GnuplotQuote(title) << "\nset xlabel 'epoch'\n"
         << "set ylabel 'loss per scan (BCE + beta KL)'\nset grid\nset key top right\n"
         << plots.str() << "\n";
  RenderGnuplotPng(script.str(), png, 900, 600);
}

}  // namespace colav

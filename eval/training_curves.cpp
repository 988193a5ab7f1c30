#include "eval/training_curves.h"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "eval/rolling_statistics.h"
#include "src/csv_table.h"
#include "src/error.h"
#include "src/figures/gnuplot.h"
#include "src/figures/style.h"

namespace colav {
namespace {

struct Panel {
  const char* title;
  const char* ylabel;
  std::vector<double> TrainingRun::*values;
  double scale;         // to the plotted unit
  double band_ceiling;  // the shaded band stops here (rates cannot exceed 100 %)
};

constexpr double kNoCeiling = std::numeric_limits<double>::infinity();

const std::array<Panel, kTrainingPanels> kPanels = {{
    {"Path progress", "progress (%)", &TrainingRun::progress, 100.0, 100.0},
    {"Cross-track error", "mean cross-track error (m)", &TrainingRun::cross_track_error, 1.0,
     kNoCeiling},
    {"Duration", "episode length (steps)", &TrainingRun::duration, 1.0, kNoCeiling},
    {"Collision rate", "collisions (%)", &TrainingRun::collision, 100.0, 100.0},
}};

// $curve<k>: x (millions of steps), then per panel the mean and the band, in plotted units.
std::string DataBlock(const TrainingCurve& curve, std::size_t index) {
  std::ostringstream block;
  block.precision(8);
  block << "$curve" << index << " << EOD\n";
  for (std::size_t i = 0; i < curve.global_step.size(); ++i) {
    block << curve.global_step[i] / 1e6;
    for (std::size_t p = 0; p < kPanels.size(); ++p) {
      const CurvePoint& point = curve.panels[p][i];
      const double scale = kPanels[p].scale;
      block << ' ' << point.mean * scale << ' ' << point.low * scale << ' '
            << std::min(kPanels[p].band_ceiling, point.high * scale);
    }
    block << '\n';
  }
  block << "EOD\n";
  return block.str();
}

std::string PanelPlot(const std::vector<TrainingCurve>& curves, std::size_t panel) {
  const int mean_column = 2 + 3 * static_cast<int>(panel);
  std::ostringstream plot;
  plot << "set title " << GnuplotQuote(kPanels[panel].title) << "\nset ylabel "
       << GnuplotQuote(kPanels[panel].ylabel) << "\n"
       << (panel == 0 ? "set key bottom right\n" : "unset key\n") << "plot ";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const std::string line_colour = LineColour(FigureColour(k));
    plot << (k == 0 ? "" : ", \\\n  ") << "$curve" << k << " using 1:" << mean_column + 1 << ":"
         << mean_column + 2 << " with filledcurves " << line_colour
         << " fs transparent solid 0.18 noborder notitle, \\\n  $curve" << k
         << " using 1:" << mean_column << " with lines lw 2 " << line_colour << " title "
         << GnuplotQuote(GnuplotEnhancedText(curves[k].label));
  }
  return plot.str() + "\n";
}

// Index of the last episode ended by `step` in `run` (which ends in step order), or -1.
std::ptrdiff_t LastEpisodeBy(const TrainingRun& run, double step) {
  const auto after = std::upper_bound(run.global_step.begin(), run.global_step.end(), step);
  return (after - run.global_step.begin()) - 1;
}

}  // namespace

TrainingRun ReadTrainingRun(const std::string& label, const std::filesystem::path& episodes_csv) {
  const CsvTable table = ReadCsvTable(episodes_csv);
  if (table.rows.empty()) throw UserError(episodes_csv.string() + ": no finished episode yet");
  return {label,
          NumericColumn(table, "global_step"),
          NumericColumn(table, "progress"),
          NumericColumn(table, "mean_cte"),
          NumericColumn(table, "steps"),
          NumericColumn(table, "collision")};
}

TrainingCurve RollingCurve(const TrainingRun& run, std::size_t window) {
  TrainingCurve curve{run.label, run.global_step, {}};
  for (std::size_t p = 0; p < kPanels.size(); ++p) {
    for (const RollingPoint& point : RollingMeanSd(run.*kPanels[p].values, window)) {
      curve.panels[p].push_back(
          {point.mean, std::max(0.0, point.mean - point.sd), point.mean + point.sd});
    }
  }
  return curve;
}

TrainingCurve SeedCurve(const std::vector<TrainingRun>& seeds, std::size_t window,
                        std::size_t grid_points) {
  if (seeds.empty() || grid_points < 2) {
    throw std::invalid_argument("SeedCurve: needs seeds and at least 2 grid points");
  }
  std::vector<TrainingCurve> rolling;
  double last_common_step = kNoCeiling;
  for (const TrainingRun& seed : seeds) {
    rolling.push_back(RollingCurve(seed, window));
    last_common_step = std::min(last_common_step, seed.global_step.back());
  }
  TrainingCurve curve{seeds.front().label, {}, {}};
  for (std::size_t g = 0; g < grid_points; ++g) {
    const double step = last_common_step * static_cast<double>(g) / (grid_points - 1);
    std::vector<std::ptrdiff_t> episode(seeds.size());
    for (std::size_t s = 0; s < seeds.size(); ++s) episode[s] = LastEpisodeBy(seeds[s], step);
    if (std::any_of(episode.begin(), episode.end(), [](std::ptrdiff_t e) { return e < 0; })) {
      continue;
    }
    curve.global_step.push_back(step);
    for (std::size_t p = 0; p < kPanels.size(); ++p) {
      CurvePoint point{0.0, kNoCeiling, -kNoCeiling};
      for (std::size_t s = 0; s < seeds.size(); ++s) {
        const double mean = rolling[s].panels[p][episode[s]].mean;
        point.mean += mean / seeds.size();
        point.low = std::min(point.low, mean);
        point.high = std::max(point.high, mean);
      }
      curve.panels[p].push_back(point);
    }
  }
  return curve;
}

void PlotTrainingCurves(const std::vector<TrainingCurve>& curves, const std::string& title,
                        const std::string& band, const std::filesystem::path& png) {
  std::ostringstream script;
  for (std::size_t k = 0; k < curves.size(); ++k) script << DataBlock(curves[k], k);
  script << MultiplotLayout(2, 2, GnuplotEnhancedText(title + " (" + band + ")")) << LightGrid()
         << "set xlabel 'environment steps (millions)'\n"
         << "set autoscale xfix\n";  // the x axis ends at the last step, not the next tic
  for (std::size_t panel = 0; panel < kPanels.size(); ++panel) script << PanelPlot(curves, panel);
  script << "unset multiplot\n";
  RenderGnuplotPng(script.str(), png, 1400, 1000);
}

}  // namespace colav

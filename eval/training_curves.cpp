#include "eval/training_curves.h"

#include <algorithm>
#include <array>
#include <limits>
#include <sstream>

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
  double band_ceiling;  // the shaded mean +- sd stops here (rates cannot exceed 100 %)
};

constexpr double kNoCeiling = std::numeric_limits<double>::infinity();

const std::array<Panel, 4> kPanels = {{
    {"Path progress", "progress (%)", &TrainingRun::progress, 100.0, 100.0},
    {"Cross-track error", "mean cross-track error (m)", &TrainingRun::cross_track_error, 1.0,
     kNoCeiling},
    {"Duration", "episode length (steps)", &TrainingRun::duration, 1.0, kNoCeiling},
    {"Collision rate", "collisions (%)", &TrainingRun::collision, 100.0, 100.0},
}};

// $run<k>: x (millions of steps), then per panel the rolling mean and the band mean -+ sd, kept
// within [0, ceiling] since every metric is non-negative.
std::string DataBlock(const TrainingRun& run, std::size_t index, std::size_t window) {
  std::vector<std::vector<RollingPoint>> rolling;
  rolling.reserve(kPanels.size());
  for (const Panel& panel : kPanels) rolling.push_back(RollingMeanSd(run.*panel.values, window));
  std::ostringstream block;
  block.precision(8);
  block << "$run" << index << " << EOD\n";
  for (std::size_t i = 0; i < run.global_step.size(); ++i) {
    block << run.global_step[i] / 1e6;
    for (std::size_t p = 0; p < kPanels.size(); ++p) {
      const double mean = rolling[p][i].mean * kPanels[p].scale;
      const double sd = rolling[p][i].sd * kPanels[p].scale;
      block << ' ' << mean << ' ' << std::max(0.0, mean - sd) << ' '
            << std::min(kPanels[p].band_ceiling, mean + sd);
    }
    block << '\n';
  }
  block << "EOD\n";
  return block.str();
}

std::string PanelPlot(const std::vector<TrainingRun>& runs, std::size_t panel) {
  const int mean_column = 2 + 3 * static_cast<int>(panel);
  std::ostringstream plot;
  plot << "set title " << GnuplotQuote(kPanels[panel].title) << "\nset ylabel "
       << GnuplotQuote(kPanels[panel].ylabel) << "\n"
       << (panel == 0 ? "set key bottom right\n" : "unset key\n") << "plot ";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const std::string line_colour = LineColour(FigureColour(k));
    plot << (k == 0 ? "" : ", \\\n  ") << "$run" << k << " using 1:" << mean_column + 1 << ":"
         << mean_column + 2 << " with filledcurves " << line_colour
         << " fs transparent solid 0.18 noborder notitle, \\\n  $run" << k
         << " using 1:" << mean_column << " with lines lw 2 " << line_colour << " title "
         << GnuplotQuote(GnuplotEnhancedText(runs[k].label));
  }
  return plot.str() + "\n";
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

void PlotTrainingCurves(const std::vector<TrainingRun>& runs, std::size_t window,
                        const std::string& title, const std::filesystem::path& png) {
  std::ostringstream script;
  for (std::size_t k = 0; k < runs.size(); ++k) script << DataBlock(runs[k], k, window);
  script << MultiplotLayout(2, 2,
                            GnuplotEnhancedText(title) + " (rolling mean and sd over " +
                                std::to_string(window) + " episodes)")
         << LightGrid() << "set xlabel 'environment steps (millions)'\n"
         << "set autoscale xfix\n";  // the x axis ends at the last step, not the next tic
  for (std::size_t panel = 0; panel < kPanels.size(); ++panel) script << PanelPlot(runs, panel);
  script << "unset multiplot\n";
  RenderGnuplotPng(script.str(), png, 1400, 1000);
}

}  // namespace colav

#include "eval/beta_sweep_figure.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <sstream>

#include "src/figures/gnuplot.h"
#include "src/figures/style.h"

namespace colav {
namespace {

struct SweepPanel {
  const char* metric;
  const char* title;
  const char* ylabel;
  double scale;
};

const std::array<SweepPanel, 4> kSweepPanels = {{
    {"progress", "Path progress", "progress (%)", 100.0},
    {"cross_track_error", "Cross-track error", "mean cross-track error (m)", 1.0},
    {"duration", "Duration", "episode length (steps)", 1.0},
    {"collision", "Collision rate", "collisions (%)", 100.0},
}};

void SortByBeta(std::vector<BetaSweepPoint>& points) {
  std::sort(points.begin(), points.end(),
            [](const BetaSweepPoint& a, const BetaSweepPoint& b) { return a.beta < b.beta; });
}

// $sweep: beta, then mean, low and high of each panel's metric.
std::string SweepDataBlock(const std::vector<BetaSweepPoint>& points) {
  std::ostringstream block;
  block.precision(10);
  block << "$sweep << EOD\n";
  for (const BetaSweepPoint& point : points) {
    block << point.beta;
    for (const SweepPanel& panel : kSweepPanels) {
      const MeanConfidenceInterval& interval =
          FindMetric(point.model.metrics, panel.metric).interval;
      block << ' ' << interval.mean * panel.scale << ' ' << interval.low * panel.scale << ' '
            << interval.high * panel.scale;
    }
    block << '\n';
  }
  return block.str() + "EOD\n";
}

}  // namespace

void PlotBetaSweep(std::vector<BetaSweepPoint> points, const std::string& title,
                   const std::filesystem::path& png) {
  SortByBeta(points);
  std::ostringstream script;
  script << SweepDataBlock(points) << MultiplotLayout(2, 2, GnuplotEnhancedText(title))
         << LightGrid() << "set xlabel 'β (KL weight of the pre-trained VAE)'\n"
         << "set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\nunset key\n";
  const std::string line_colour = LineColour(FigureColour(0));
  for (std::size_t p = 0; p < kSweepPanels.size(); ++p) {
    const int mean = 2 + 3 * static_cast<int>(p);
    script << "set title " << GnuplotQuote(kSweepPanels[p].title) << "\nset ylabel "
           << GnuplotQuote(kSweepPanels[p].ylabel) << "\nplot $sweep using 1:" << mean << ":"
           << mean + 1 << ":" << mean + 2 << " with yerrorbars pt 7 ps 1.2 " << line_colour
           << ", $sweep using 1:" << mean << " with lines lw 1.5 " << line_colour << "\n";
  }
  script << "unset multiplot\n";
  RenderGnuplotPng(script.str(), png, 1200, 900);
}

std::string BetaSweepTable(std::vector<BetaSweepPoint> points) {
  SortByBeta(points);
  std::ostringstream table;
  table << "| beta | model |";
  for (const SweepPanel& panel : kSweepPanels) table << ' ' << panel.ylabel << " |";
  table << "\n|---|---|---|---|---|---|\n";
  for (const BetaSweepPoint& point : points) {
    char beta[32];
    std::snprintf(beta, sizeof beta, "%g", point.beta);
    table << "| " << beta << " | " << point.model.name << " |";
    for (const SweepPanel& panel : kSweepPanels) {
      const MeanConfidenceInterval& interval =
          FindMetric(point.model.metrics, panel.metric).interval;
      char cell[80];
      std::snprintf(cell, sizeof cell, " %.1f [%.1f, %.1f] |", interval.mean * panel.scale,
                    interval.low * panel.scale, interval.high * panel.scale);
      table << cell;
    }
    table << '\n';
  }
  return table.str();
}

}  // namespace colav

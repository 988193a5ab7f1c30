#include "eval/trajectory_figure.h"

#include <cstdio>

#include "env/scene_plot.h"
#include "src/figures/gnuplot.h"

namespace colav {
namespace {

std::string RunLabel(const std::string& label, const EpisodeMetrics& metrics) {
  char text[160];
  std::snprintf(text, sizeof text, "%s: reward %.0f, progress %.0f %%%s", label.c_str(),
                metrics.cumulative_reward, 100.0 * metrics.progress,
                metrics.collision ? ", collision" : "");
  return text;
}

}  // namespace

void PlotTrajectories(const Scenario& scenario, const std::string& scenario_name,
                      const std::string& model_name, const std::vector<EpisodeOutcome>& runs,
                      const std::vector<std::string>& labels, const std::filesystem::path& png) {
  std::vector<SceneTrack> tracks;
  int collisions = 0;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const EpisodeOutcome& run = runs[k];
    const std::vector<double> colour =
        runs.size() == 1 ? run.cumulative_rewards
                         : std::vector<double>(run.positions.size(), run.metrics.cumulative_reward);
    tracks.push_back({GnuplotEnhancedText(RunLabel(labels[k], run.metrics)), run.positions, colour,
                      run.metrics.collision});
    collisions += run.metrics.collision ? 1 : 0;
  }
  const std::string title =
      GnuplotEnhancedText(scenario_name + ": " + model_name) +
      (runs.size() == 1 ? std::string(" (one run)")
                        : " (" + std::to_string(runs.size()) + " starts, " +
                              std::to_string(collisions) + " with a collision)");
  PlotScene(scenario, tracks, runs.front().metrics.steps, png, title);
}

std::filesystem::path TrajectoryFigurePath(const std::filesystem::path& dir,
                                           const std::string& scenario_name,
                                           const std::string& model_name) {
  return dir / "figures" / (scenario_name + "_" + model_name + ".png");
}

}  // namespace colav

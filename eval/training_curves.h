// The paper's training-curve figure: path progress, cross-track error, duration and collision rate
// of the training episodes against environment steps (four panels), as rolling means over the last
// episodes. One run is drawn with its rolling standard deviation shaded (the paper's figure); a
// configuration trained with several seeds as the mean over its seeds of their rolling means, with
// the range over the seeds shaded, which shows how far one seed's curve can be trusted.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace colav {

/// The finished training episodes of one train_ppo run, in the order they ended.
struct TrainingRun {
  std::string label;
  std::vector<double> global_step;
  std::vector<double> progress;           ///< fraction
  std::vector<double> cross_track_error;  ///< m
  std::vector<double> duration;           ///< steps
  std::vector<double> collision;          ///< 0/1
};

/// Reads a train_ppo episodes.csv (columns global_step, progress, mean_cte, steps, collision;
/// others ignored). UserError naming the file on a missing file, column or bad value, or when it
/// holds no episode.
TrainingRun ReadTrainingRun(const std::string& label, const std::filesystem::path& episodes_csv);

/// A line with a shaded band, in the runs' units (fractions, m, steps).
struct CurvePoint {
  double mean = 0.0;
  double low = 0.0;
  double high = 0.0;
};

inline constexpr std::size_t kTrainingPanels = 4;  ///< progress, cte, duration, collisions

/// What one line of the figure shows: points at `global_step`, per panel.
struct TrainingCurve {
  std::string label;
  std::vector<double> global_step;
  std::array<std::vector<CurvePoint>, kTrainingPanels> panels;
};

/// One run: at each finished episode, the rolling mean over `window` episodes, band mean -+ sd
/// (never below 0).
TrainingCurve RollingCurve(const TrainingRun& run, std::size_t window);

/// The seeds of one configuration (labelled by the first): on `grid_points` steps evenly spread up
/// to the step all seeds reached, each seed's rolling mean of its last episode ended by then,
/// averaged over the seeds, band the lowest to the highest seed. Grid steps before a seed's first
/// episode are left out.
TrainingCurve SeedCurve(const std::vector<TrainingRun>& seeds, std::size_t window,
                        std::size_t grid_points);

/// Draws the four panels of `curves` to `png`; `band` names the shading in the title.
void PlotTrainingCurves(const std::vector<TrainingCurve>& curves, const std::string& title,
                        const std::string& band, const std::filesystem::path& png);

}  // namespace colav

// The paper's training-curve figure: path progress, cross-track error, duration and collision rate
// of the training episodes against environment steps, as rolling means over the last episodes with
// a shaded rolling standard deviation, several runs on one figure (four panels).
#pragma once

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

/// Draws the four panels for `runs` (rolling window of `window` episodes) to `png`.
void PlotTrainingCurves(const std::vector<TrainingRun>& runs, std::size_t window,
                        const std::string& title, const std::filesystem::path& png);

}  // namespace colav

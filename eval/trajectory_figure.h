// The trajectory figure of the paper: a model's runs through one scene, coloured by reward.
//
// With several runs, each track has one colour, the return its agent collected (the paper's
// style: collided runs stand out in red). A single run would then be one colour on a degenerate
// scale, so it is coloured point by point by the cumulative reward so far instead.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "env/scenario.h"
#include "eval/episode_runner.h"

namespace colav {

/// Draws `runs` (the model's runs of `scenario`, possibly from different starts; runs[0] sets the
/// time at which moving obstacles are drawn filled) to `png`. `labels[k]` names run k.
void PlotTrajectories(const Scenario& scenario, const std::string& scenario_name,
                      const std::string& model_name, const std::vector<EpisodeOutcome>& runs,
                      const std::vector<std::string>& labels, const std::filesystem::path& png);

/// DIR/figures/<scenario>_<model>.png.
std::filesystem::path TrajectoryFigurePath(const std::filesystem::path& dir,
                                           const std::string& scenario_name,
                                           const std::string& model_name);

}  // namespace colav

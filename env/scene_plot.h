// Pictures of a scene: path, obstacles at the start and the end, vessel tracks, collisions.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "env/scenario.h"

namespace colav {

/// One vessel track over a scene.
struct SceneTrack {
  std::string label;
  std::vector<Eigen::Vector2d> positions;  ///< row 0 = reset position
  /// Optional per-position colour value (e.g. cumulative reward); empty = one colour per track.
  std::vector<double> colour_values;
  bool collision = false;
};

/// Draws the scenario with moving obstacles at the start (outlined) and after `steps` seconds
/// (filled), and the tracks, to a PNG with gnuplot.
void PlotScene(const Scenario& scenario, const std::vector<SceneTrack>& tracks, std::int64_t steps,
               const std::filesystem::path& png, const std::string& title,
               const std::string& colour_label = "cumulative reward");

}  // namespace colav

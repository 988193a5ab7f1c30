#include "env/scene_plot.h"

#include <cmath>
#include <sstream>

#include "env/obstacles.h"
#include "env/path.h"
#include "src/figures/gnuplot.h"
#include "src/figures/style.h"

namespace colav {
namespace {

// Margin around the drawn objects (m).
constexpr double kMargin = 30.0;

constexpr const char* kPathColour = "#1a9850";
constexpr const char* kStaticObstacleColour = "#7f7f7f";
constexpr const char* kVesselColour = "#e08214";
constexpr const char* kTrackColour = "#2166ac";
// Diverging red-white-blue for the tracks coloured by reward: red where it is low.
constexpr const char* kTrackPalette = "(0 '#b2182b', 0.5 '#f7f7f7', 1 '#2166ac')";

void AppendPolygon(std::ostringstream& out, const ConvexPolygon& hull) {
  for (int k = 0; k <= hull.size; ++k) {
    const Eigen::Vector2d& v = hull.vertices[k % hull.size];
    out << v.x() << ' ' << v.y() << '\n';
  }
  out << '\n';
}

void AppendCircle(std::ostringstream& out, const CircleSpec& circle) {
  constexpr int kSegments = 72;
  for (int k = 0; k <= kSegments; ++k) {
    const double angle = 2.0 * 3.14159265358979323846 * k / kSegments;
    out << circle.center.x() + circle.radius * std::cos(angle) << ' '
        << circle.center.y() + circle.radius * std::sin(angle) << '\n';
  }
  out << '\n';
}

// Inline data blocks: $path, $static, $start_hulls, $end_hulls, $track<k>.
std::string DataBlocks(const Scenario& scenario, const std::vector<SceneTrack>& tracks,
                       std::int64_t steps) {
  std::ostringstream out;
  out.precision(10);
  const Path path(scenario.waypoints);
  out << "$path << EOD\n";
  for (double s = 0.0; s < path.length(); s += 1.0) {
    out << path.Point(s).x() << ' ' << path.Point(s).y() << '\n';
  }
  out << path.end().x() << ' ' << path.end().y() << "\nEOD\n$static << EOD\n";
  for (const CircleSpec& circle : scenario.static_obstacles) AppendCircle(out, circle);
  out << "\nEOD\n$start_hulls << EOD\n";
  for (const VesselObstacleSpec& spec : scenario.dynamic_obstacles) {
    AppendPolygon(out, VesselHull(spec.position, spec.width, spec.course));
  }
  out << "\nEOD\n$end_hulls << EOD\n";
  for (const VesselObstacleSpec& spec : scenario.dynamic_obstacles) {
    MovingObstacle obstacle(spec);
    obstacle.Advance(static_cast<double>(steps));
    AppendPolygon(out, obstacle.hull());
  }
  out << "\nEOD\n";
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    out << "$track" << t << " << EOD\n";
    const SceneTrack& track = tracks[t];
    for (std::size_t k = 0; k < track.positions.size(); ++k) {
      out << track.positions[k].x() << ' ' << track.positions[k].y() << ' '
          << (track.colour_values.empty() ? 0.0 : track.colour_values[k]) << '\n';
    }
    out << "EOD\n";
  }
  return out.str();
}

// A square view around the path, the start and the tracks.
std::string ViewRange(const Scenario& scenario, const std::vector<SceneTrack>& tracks) {
  const Path path(scenario.waypoints);
  Eigen::Vector2d lower = path.start().cwiseMin(scenario.vessel_position);
  Eigen::Vector2d upper = path.start().cwiseMax(scenario.vessel_position);
  for (double s = 0.0; s <= path.length(); s += 5.0) {
    lower = lower.cwiseMin(path.Point(s));
    upper = upper.cwiseMax(path.Point(s));
  }
  for (const SceneTrack& track : tracks) {
    for (const Eigen::Vector2d& p : track.positions) {
      lower = lower.cwiseMin(p);
      upper = upper.cwiseMax(p);
    }
  }
  const Eigen::Vector2d center = (lower + upper) / 2.0;
  const double half = (upper - lower).maxCoeff() / 2.0 + kMargin;
  std::ostringstream out;
  out << "set xrange [" << center.x() - half << ":" << center.x() + half << "]\n"
      << "set yrange [" << center.y() - half << ":" << center.y() + half << "]\n";
  return out.str();
}

}  // namespace

void PlotScene(const Scenario& scenario, const std::vector<SceneTrack>& tracks, std::int64_t steps,
               const std::filesystem::path& png, const std::string& title,
               const std::string& colour_label) {
  std::ostringstream script;
  script << DataBlocks(scenario, tracks, steps) << ViewRange(scenario, tracks)
         << "set size ratio -1\n"
         << LightGrid() << "set key outside bottom center horizontal\n"
         << "set xlabel 'x (m)'\nset ylabel 'y (m)'\nset title " << GnuplotQuote(title) << "\n";
  bool coloured = false;
  for (const SceneTrack& track : tracks) coloured |= !track.colour_values.empty();
  if (coloured) {
    script << "set palette defined " << kTrackPalette << "\n"
           << "set cblabel " << GnuplotQuote(colour_label) << "\n";
  }
  script << "plot $static with filledcurves " << LineColour(kStaticObstacleColour)
         << " fs transparent solid 0.6 title 'static obstacles', \\\n"
         << "  $start_hulls with lines " << LineColour(kVesselColour)
         << " dt 2 title 'vessels at start', \\\n"
         << "  $end_hulls with filledcurves " << LineColour(kVesselColour)
         << " fs transparent solid 0.5 title 'vessels at end', \\\n"
         << "  $path with lines lw 2 " << LineColour(kPathColour) << " title 'path'";
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    const SceneTrack& track = tracks[t];
    script << ", \\\n  $track" << t << " using 1:2"
           << (track.colour_values.empty() ? " with lines lw 2 " + LineColour(kTrackColour)
                                           : std::string(":3 with lines lw 2 lc palette"))
           << " title " << GnuplotQuote(track.label);
    if (track.collision && !track.positions.empty()) {
      script << ", \\\n  $track" << t << " every ::" << track.positions.size() - 1
             << " using 1:2 with points pt 3 ps 3 lw 3 " << LineColour("red")
             << " title 'collision'";
    }
  }
  script << ", \\\n  '+' using (" << scenario.vessel_position.x() << "):("
         << scenario.vessel_position.y() << ") every ::0::0 with points pt 7 ps 1.5 "
         << LineColour("black") << " title 'start'\n";
  RenderGnuplotPng(script.str(), png);
}

}  // namespace colav

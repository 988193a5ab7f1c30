// The smooth path the vessel follows: waypoints smoothed by three PCHIP refits, its length,
// direction, and the reference's dense-polyline projection (reference-simulator 4.2-4.3).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "env/pchip.h"
#include "env/polyline_projector.h"

namespace colav {

class Path {
 public:
  /// Smooths the waypoints (at least 2, consecutive ones distinct).
  explicit Path(const std::vector<Eigen::Vector2d>& waypoints);

  /// Path point at arclength parameter s (extrapolated outside [0, L]).
  Eigen::Vector2d Point(double s) const { return curve_.Evaluate(s); }
  /// Path direction (rad) at s: atan2 of the derivative.
  double Direction(double s) const;
  /// s* of the point nearest `position` on the dense polyline (first segment on ties).
  double ClosestArclength(const Eigen::Vector2d& position) const {
    return projector_.Project(position);
  }

  double length() const { return length_; }
  Eigen::Vector2d start() const { return Point(0.0); }
  Eigen::Vector2d end() const { return Point(length_); }
  const PolylineProjector& projector() const { return projector_; }

 private:
  PchipCurve curve_;
  double length_;
  PolylineProjector projector_;
};

/// Cumulative chord lengths of a point list (first entry 0).
std::vector<double> CumulativeChordLengths(const std::vector<Eigen::Vector2d>& points);

/// numpy.linspace(start, stop, count): i * step + start, the last value exactly stop.
std::vector<double> Linspace(double start, double stop, std::size_t count);

}  // namespace colav

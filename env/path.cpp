#include "env/path.h"

#include <cmath>
#include <stdexcept>

namespace colav {
namespace {

// Smoothing passes and samples per pass of the reference Path [path.py:22-27].
constexpr int kSmoothingPasses = 3;
constexpr std::size_t kSamplesPerPass = 1000;
// The projection polyline has this many vertices per metre of (rounded) length [path.py:35-37].
constexpr double kProjectionVerticesPerMetre = 10.0;

// Fits the PCHIP of the third pass (the path function), resampling after passes 1 and 2.
PchipCurve SmoothedCurve(const std::vector<Eigen::Vector2d>& waypoints) {
  std::vector<Eigen::Vector2d> points = waypoints;
  for (int pass = 1;; ++pass) {
    std::vector<double> knots = CumulativeChordLengths(points);
    PchipCurve curve(knots, points);
    if (pass == kSmoothingPasses) return curve;
    const std::vector<double> samples = Linspace(knots.front(), knots.back(), kSamplesPerPass);
    points.resize(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k) points[k] = curve.Evaluate(samples[k]);
  }
}

std::vector<Eigen::Vector2d> ProjectionVertices(const PchipCurve& curve, double length) {
  // R = round(L) with Python's round-half-to-even; K = 10 R vertices on [0, R].
  const double rounded = std::nearbyint(length);
  const auto count = static_cast<std::size_t>(kProjectionVerticesPerMetre * rounded);
  if (count < 2) throw std::invalid_argument("Path: shorter than 1 m");
  const std::vector<double> samples = Linspace(0.0, rounded, count);
  std::vector<Eigen::Vector2d> vertices(count);
  for (std::size_t k = 0; k < count; ++k) vertices[k] = curve.Evaluate(samples[k]);
  return vertices;
}

}  // namespace

std::vector<double> CumulativeChordLengths(const std::vector<Eigen::Vector2d>& points) {
  std::vector<double> lengths(points.size(), 0.0);
  for (std::size_t k = 1; k < points.size(); ++k) {
    const Eigen::Vector2d delta = points[k] - points[k - 1];
    lengths[k] = lengths[k - 1] + std::sqrt(delta.x() * delta.x() + delta.y() * delta.y());
  }
  return lengths;
}

std::vector<double> Linspace(double start, double stop, std::size_t count) {
  std::vector<double> values(count);
  const double step = (stop - start) / static_cast<double>(count - 1);
  for (std::size_t k = 0; k < count; ++k) values[k] = static_cast<double>(k) * step + start;
  values[count - 1] = stop;
  return values;
}

Path::Path(const std::vector<Eigen::Vector2d>& waypoints)
    : curve_(SmoothedCurve(waypoints)),
      length_(curve_.knots().back()),
      projector_(ProjectionVertices(curve_, length_)) {}

double Path::Direction(double s) const {
  const Eigen::Vector2d derivative = curve_.Derivative(s);
  return std::atan2(derivative.y(), derivative.x());
}

}  // namespace colav

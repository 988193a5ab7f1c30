// Piecewise cubic Hermite interpolation (PCHIP) of a planar curve, with scipy's
// PchipInterpolator slopes and evaluation (reference-simulator 4.2).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace colav {

class PchipCurve {
 public:
  /// Interpolates points[k] at strictly increasing knots[k] (at least 2 of each).
  PchipCurve(std::vector<double> knots, const std::vector<Eigen::Vector2d>& points);

  /// Curve point at parameter s; outside the knots the first/last cubic piece extrapolates.
  Eigen::Vector2d Evaluate(double s) const;
  /// Derivative d/ds of the curve at s.
  Eigen::Vector2d Derivative(double s) const;

  const std::vector<double>& knots() const { return knots_; }

 private:
  /// Index of the piece containing s: largest k with knots[k] <= s, clamped to the pieces.
  std::size_t PieceIndex(double s) const;

  std::vector<double> knots_;
  /// Per piece, ascending-power coefficients (c0 + c1 t + c2 t^2 + c3 t^3, t = s - knot).
  std::vector<Eigen::Matrix<double, 2, 4>> coefficients_;
};

/// Slopes of the 1-D PCHIP through (x, y) (scipy's rules, including the end-point formula).
std::vector<double> PchipSlopes(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace colav

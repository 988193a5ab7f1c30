#include "env/pchip.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace colav {
namespace {

int Sign(double value) { return (value > 0.0) - (value < 0.0); }

// scipy's PchipInterpolator._edge_case: a three-point estimate, kept monotone.
double EdgeSlope(double h0, double h1, double m0, double m1) {
  double d = ((2.0 * h0 + h1) * m0 - h0 * m1) / (h0 + h1);
  if (Sign(d) != Sign(m0)) {
    d = 0.0;
  } else if (Sign(m0) != Sign(m1) && std::fabs(d) > std::fabs(3.0 * m0)) {
    d = 3.0 * m0;
  }
  return d;
}

}  // namespace

std::vector<double> PchipSlopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> h(n - 1);
  std::vector<double> m(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = x[k + 1] - x[k];
    m[k] = (y[k + 1] - y[k]) / h[k];
  }
  std::vector<double> d(n);
  if (n == 2) {
    d[0] = d[1] = m[0];
    return d;
  }
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (m[k - 1] == 0.0 || m[k] == 0.0 || Sign(m[k - 1]) != Sign(m[k])) {
      d[k] = 0.0;
    } else {
      // Weighted harmonic mean, written as scipy does.
      const double w1 = 2.0 * h[k] + h[k - 1];
      const double w2 = h[k] + 2.0 * h[k - 1];
      const double whmean = (w1 / m[k - 1] + w2 / m[k]) / (w1 + w2);
      d[k] = 1.0 / whmean;
    }
  }
  d[0] = EdgeSlope(h[0], h[1], m[0], m[1]);
  d[n - 1] = EdgeSlope(h[n - 2], h[n - 3], m[n - 2], m[n - 3]);
  return d;
}

PchipCurve::PchipCurve(std::vector<double> knots, const std::vector<Eigen::Vector2d>& points)
    : knots_(std::move(knots)) {
  const std::size_t n = knots_.size();
  if (n < 2 || points.size() != n) {
    throw std::invalid_argument("PchipCurve: need at least 2 knots, one point per knot");
  }
  std::vector<double> xs(n);
  std::vector<double> ys(n);
  for (std::size_t k = 0; k < n; ++k) {
    xs[k] = points[k].x();
    ys[k] = points[k].y();
  }
  const std::vector<double> dx = PchipSlopes(knots_, xs);
  const std::vector<double> dy = PchipSlopes(knots_, ys);
  coefficients_.resize(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    // CubicHermiteSpline coefficients, in scipy's operation order.
    const double h = knots_[k + 1] - knots_[k];
    const Eigen::Vector2d& y0 = points[k];
    const Eigen::Vector2d slope = (points[k + 1] - points[k]) / h;
    const Eigen::Vector2d d0(dx[k], dy[k]);
    const Eigen::Vector2d d1(dx[k + 1], dy[k + 1]);
    const Eigen::Vector2d t = (d0 + d1 - 2.0 * slope) / h;
    coefficients_[k].col(0) = y0;
    coefficients_[k].col(1) = d0;
    coefficients_[k].col(2) = (slope - d0) / h - t;
    coefficients_[k].col(3) = t / h;
  }
}

std::size_t PchipCurve::PieceIndex(double s) const {
  const auto upper = std::upper_bound(knots_.begin(), knots_.end(), s);
  const std::ptrdiff_t index = (upper - knots_.begin()) - 1;
  return static_cast<std::size_t>(
      std::clamp<std::ptrdiff_t>(index, 0, static_cast<std::ptrdiff_t>(coefficients_.size()) - 1));
}

Eigen::Vector2d PchipCurve::Evaluate(double s) const {
  const std::size_t k = PieceIndex(s);
  const double t = s - knots_[k];
  const auto& c = coefficients_[k];
  // Ascending powers, as scipy's evaluate_poly1.
  return c.col(0) + c.col(1) * t + c.col(2) * (t * t) + c.col(3) * (t * t * t);
}

Eigen::Vector2d PchipCurve::Derivative(double s) const {
  const std::size_t k = PieceIndex(s);
  const double t = s - knots_[k];
  const auto& c = coefficients_[k];
  return c.col(1) + 2.0 * c.col(2) * t + 3.0 * c.col(3) * (t * t);
}

}  // namespace colav

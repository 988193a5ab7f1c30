#include "train/dataset/shape_overlap.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace colav {
namespace {

// The interval the polygon's vertices cover along `axis`.
std::pair<double, double> Project(const ConvexPolygon& polygon, const Eigen::Vector2d& axis) {
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (int k = 0; k < polygon.size; ++k) {
    const double value = axis.dot(polygon.vertices[k]);
    low = std::min(low, value);
    high = std::max(high, value);
  }
  return {low, high};
}

// True when one of `owner`'s edge normals separates the two polygons.
bool HasSeparatingNormal(const ConvexPolygon& owner, const ConvexPolygon& other) {
  for (int k = 0; k < owner.size; ++k) {
    const auto [low_a, high_a] = Project(owner, owner.normals[k]);
    const auto [low_b, high_b] = Project(other, owner.normals[k]);
    if (high_a < low_b || high_b < low_a) return true;
  }
  return false;
}

}  // namespace

bool CirclesOverlap(const CircleSpec& a, const CircleSpec& b) {
  const double reach = a.radius + b.radius;
  return (a.center - b.center).squaredNorm() <= reach * reach;
}

bool CirclePolygonOverlap(const CircleSpec& circle, const ConvexPolygon& polygon) {
  return DistanceToPolygon(circle.center, polygon) <= circle.radius;
}

bool PolygonsOverlap(const ConvexPolygon& a, const ConvexPolygon& b) {
  return !HasSeparatingNormal(a, b) && !HasSeparatingNormal(b, a);
}

}  // namespace colav

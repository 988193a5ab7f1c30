#include "train/dataset/shape_overlap.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace colav {
namespace {

// Squared distance from p to the segment [a, b].
double SquaredDistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b) {
  const Eigen::Vector2d edge = b - a;
  const double t = std::clamp((p - a).dot(edge) / edge.squaredNorm(), 0.0, 1.0);
  return (a + t * edge - p).squaredNorm();
}

bool ContainsPoint(const ConvexPolygon& polygon, const Eigen::Vector2d& point) {
  for (int k = 0; k < polygon.size; ++k) {
    if (polygon.normals[k].dot(point - polygon.vertices[k]) > 0.0) return false;
  }
  return true;
}

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
  if (ContainsPoint(polygon, circle.center)) return true;
  const double radius_squared = circle.radius * circle.radius;
  for (int k = 0; k < polygon.size; ++k) {
    const Eigen::Vector2d& a = polygon.vertices[k];
    const Eigen::Vector2d& b = polygon.vertices[(k + 1) % polygon.size];
    if (SquaredDistanceToSegment(circle.center, a, b) <= radius_squared) return true;
  }
  return false;
}

bool PolygonsOverlap(const ConvexPolygon& a, const ConvexPolygon& b) {
  return !HasSeparatingNormal(a, b) && !HasSeparatingNormal(b, a);
}

}  // namespace colav

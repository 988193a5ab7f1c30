#include "env/ray_geometry.h"

#include <algorithm>
#include <cmath>

namespace colav {

double RayCircleDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                         const Eigen::Vector2d& center, double radius, double max_range) {
  const Eigen::Vector2d to_center = center - origin;
  const double c = to_center.squaredNorm() - radius * radius;
  if (c < 0.0) return 0.0;  // inside the circle
  const double b = direction.dot(to_center);
  if (b < 0.0) return max_range;  // circle behind the origin
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return max_range;
  const double t = b - std::sqrt(discriminant);
  return t <= max_range ? t : max_range;
}

double RayPolygonDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                          const ConvexPolygon& polygon, double max_range) {
  double enter = 0.0;
  double exit = max_range;
  for (int k = 0; k < polygon.size; ++k) {
    const Eigen::Vector2d& normal = polygon.normals[k];
    // Inside edge k's half-plane: normal . (origin + t d - vertex) <= 0.
    const double offset = normal.dot(origin - polygon.vertices[k]);
    const double rate = normal.dot(direction);
    if (rate == 0.0) {
      if (offset > 0.0) return max_range;  // parallel and outside
      continue;
    }
    const double t = -offset / rate;
    if (rate < 0.0) {
      enter = std::max(enter, t);
    } else {
      exit = std::min(exit, t);
    }
    if (enter > exit) return max_range;
  }
  return enter;
}

}  // namespace colav

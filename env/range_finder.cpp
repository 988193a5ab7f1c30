#include "env/range_finder.h"

#include <algorithm>
#include <cmath>

#include "env/ray_geometry.h"

namespace colav {

RangeFinder::RangeFinder(double first_ray_angle) : first_ray_angle_(first_ray_angle) {
  for (int i = 0; i < kNumRays; ++i) {
    const double angle = first_ray_angle + i * kRaySpacing;
    relative_directions_[i] = Eigen::Vector2d(std::cos(angle), std::sin(angle));
  }
}

template <typename RayTest>
void RangeFinder::ForRaysNear(const Eigen::Vector2d& origin, double heading,
                              const Eigen::Vector2d& center, double radius,
                              const RayTest& test) const {
  const Eigen::Vector2d offset = center - origin;
  const double distance = offset.norm();
  if (distance - radius > kRange) return;
  const double c = std::cos(heading);
  const double s = std::sin(heading);
  const auto run = [&](int ray) {
    const Eigen::Vector2d& rel = relative_directions_[ray];
    test(ray, Eigen::Vector2d(c * rel.x() - s * rel.y(), s * rel.x() + c * rel.y()));
  };
  if (distance <= radius) {
    for (int ray = 0; ray < kNumRays; ++ray) run(ray);
    return;
  }
  // Rays within the subtended half-angle of the bearing, plus one ray of margin each side so
  // rounding never drops a ray; the exact test decides.
  const double half_angle = std::asin(radius / distance);
  const double bearing = std::atan2(offset.y(), offset.x()) - heading - first_ray_angle_;
  const int first = static_cast<int>(std::floor((bearing - half_angle) / kRaySpacing)) - 1;
  const int last = static_cast<int>(std::ceil((bearing + half_angle) / kRaySpacing)) + 1;
  for (int k = first; k <= std::min(last, first + kNumRays - 1); ++k) {
    run(((k % kNumRays) + kNumRays) % kNumRays);
  }
}

void RangeFinder::Scan(const Eigen::Vector2d& origin, double heading,
                       const std::vector<CircleSpec>& circles,
                       const std::vector<const ConvexPolygon*>& polygons, double* ranges) const {
  std::fill(ranges, ranges + kNumRays, kRange);
  for (const CircleSpec& circle : circles) {
    ForRaysNear(origin, heading, circle.center, circle.radius,
                [&](int ray, const Eigen::Vector2d& direction) {
                  ranges[ray] = std::min(
                      ranges[ray],
                      RayCircleDistance(origin, direction, circle.center, circle.radius, kRange));
                });
  }
  for (const ConvexPolygon* polygon : polygons) {
    ForRaysNear(origin, heading, polygon->bound_center, polygon->bound_radius,
                [&](int ray, const Eigen::Vector2d& direction) {
                  ranges[ray] = std::min(ranges[ray],
                                         RayPolygonDistance(origin, direction, *polygon, kRange));
                });
  }
}

double Closeness(double range, ClosenessTransform transform) {
  const double clipped = std::clamp(range, 0.0, RangeFinder::kRange);
  if (transform == ClosenessTransform::kLog) {
    return 1.0 - std::clamp(std::log1p(clipped) / std::log(RangeFinder::kRange + 1.0), 0.0, 1.0);
  }
  return 1.0 - clipped / RangeFinder::kRange;
}

}  // namespace colav

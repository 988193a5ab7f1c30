#include "env/obstacles.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace colav {

ConvexPolygon VesselHull(const Eigen::Vector2d& position, double width, double heading) {
  const double h = width / 2.0;
  const std::array<Eigen::Vector2d, 5> local = {
      Eigen::Vector2d(-h, -h), Eigen::Vector2d(-h, h), Eigen::Vector2d(h, h),
      Eigen::Vector2d(3.0 * h, 0.0), Eigen::Vector2d(h, -h)};
  const double c = std::cos(heading);
  const double s = std::sin(heading);
  ConvexPolygon polygon;
  polygon.size = 5;
  for (int k = 0; k < 5; ++k) {
    const Eigen::Vector2d& v = local[k];
    polygon.vertices[k] = position + Eigen::Vector2d(c * v.x() - s * v.y(), s * v.x() + c * v.y());
  }
  // The local vertex list runs clockwise, so the outward normal of edge e is (-e_y, e_x).
  for (int k = 0; k < 5; ++k) {
    const Eigen::Vector2d edge = polygon.vertices[(k + 1) % 5] - polygon.vertices[k];
    polygon.normals[k] = Eigen::Vector2d(-edge.y(), edge.x()).normalized();
  }
  polygon.bound_center = position;
  polygon.bound_radius = 3.0 * h;  // the bow vertex is the farthest from the local origin
  return polygon;
}

void Translate(ConvexPolygon& polygon, const Eigen::Vector2d& offset) {
  for (int k = 0; k < polygon.size; ++k) polygon.vertices[k] += offset;
  polygon.bound_center += offset;
}

double DistanceToPolygon(const Eigen::Vector2d& point, const ConvexPolygon& polygon) {
  bool inside = true;
  double nearest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < polygon.size; ++k) {
    const Eigen::Vector2d& start = polygon.vertices[k];
    const Eigen::Vector2d edge = polygon.vertices[(k + 1) % polygon.size] - start;
    if (polygon.normals[k].dot(point - start) > 0.0) inside = false;
    const double along = std::clamp((point - start).dot(edge) / edge.squaredNorm(), 0.0, 1.0);
    nearest = std::min(nearest, (start + along * edge - point).norm());
  }
  return inside ? 0.0 : nearest;
}

double DistanceToCircleBoundary(const Eigen::Vector2d& point, const CircleSpec& circle) {
  return std::fabs((point - circle.center).norm() - circle.radius);
}

MovingObstacle::MovingObstacle(const VesselObstacleSpec& spec)
    : spec_(spec),
      velocity_(spec.speed * std::cos(spec.course), spec.speed * std::sin(spec.course)),
      position_(spec.position),
      hull_(VesselHull(spec.position, spec.width, spec.course)) {}

void MovingObstacle::Advance(double dt) {
  const Eigen::Vector2d displacement = velocity_ * dt;
  position_ += displacement;
  Translate(hull_, displacement);
}

}  // namespace colav

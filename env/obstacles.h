// Obstacle geometry: static circles and moving vessels (convex pentagon hulls).
#pragma once

#include <Eigen/Core>
#include <array>

#include "env/scenario.h"

namespace colav {

/// A convex polygon with its outward edge normals and a bounding circle, in world coordinates.
struct ConvexPolygon {
  static constexpr int kMaxVertices = 5;
  std::array<Eigen::Vector2d, kMaxVertices> vertices;
  std::array<Eigen::Vector2d, kMaxVertices> normals;  ///< outward normal of edge k -> k+1
  int size = 0;
  Eigen::Vector2d bound_center = Eigen::Vector2d::Zero();
  double bound_radius = 0.0;
};

/// Pentagon hull of a vessel of width w, bow along +x (reference-simulator 5.2), rotated by
/// `heading` about the local origin and translated to `position`.
ConvexPolygon VesselHull(const Eigen::Vector2d& position, double width, double heading);

/// Moves a polygon by `offset` (vertices and bounding circle).
void Translate(ConvexPolygon& polygon, const Eigen::Vector2d& offset);

/// Distance from `point` to the filled polygon: 0 inside, else to its nearest edge.
double DistanceToPolygon(const Eigen::Vector2d& point, const ConvexPolygon& polygon);

/// Distance from `point` to the circle's boundary (the reference measures a static obstacle by
/// its ring, so a point inside is as far as the ring is).
double DistanceToCircleBoundary(const Eigen::Vector2d& point, const CircleSpec& circle);

/// A vessel moving at constant velocity along its course.
class MovingObstacle {
 public:
  explicit MovingObstacle(const VesselObstacleSpec& spec);

  /// Moves by velocity * dt.
  void Advance(double dt);

  const VesselObstacleSpec& spec() const { return spec_; }
  const Eigen::Vector2d& position() const { return position_; }
  /// m/s, world frame: speed along the course.
  const Eigen::Vector2d& velocity() const { return velocity_; }
  const ConvexPolygon& hull() const { return hull_; }

 private:
  VesselObstacleSpec spec_;
  Eigen::Vector2d velocity_;
  Eigen::Vector2d position_;
  ConvexPolygon hull_;
};

}  // namespace colav

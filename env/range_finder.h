// The 180-ray range-finder (reference-simulator 6).
//
// A step costs what it must: obstacles out of range are skipped, and each obstacle is tested
// only against the rays inside the angular interval its bounding circle subtends.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "env/environment_spec.h"
#include "env/obstacles.h"
#include "env/scenario.h"

namespace colav {

class RangeFinder {
 public:
  static constexpr double kRange = 150.0;  ///< m; also the reading of a ray without a return
  static constexpr double kRaySpacing = 2.0 * 3.14159265358979323846 / kNumRays;
  /// Relative angle of ray 0 in the simulator: ray i at -pi + (i+1) * 2 deg (ray 89 ahead).
  static constexpr double kVesselFirstRayAngle = -3.14159265358979323846 + kRaySpacing;

  /// Ray i points at first_ray_angle + i * 2 deg relative to the sensor's heading.
  explicit RangeFinder(double first_ray_angle = kVesselFirstRayAngle);

  /// Writes the kNumRays ranges (m) seen from `origin` with heading `heading`.
  void Scan(const Eigen::Vector2d& origin, double heading, const std::vector<CircleSpec>& circles,
            const std::vector<const ConvexPolygon*>& polygons, double* ranges) const;

 private:
  /// Calls test(ray, direction) for every ray that may hit a shape bounded by the circle.
  template <typename RayTest>
  void ForRaysNear(const Eigen::Vector2d& origin, double heading, const Eigen::Vector2d& center,
                   double radius, const RayTest& test) const;

  double first_ray_angle_;
  std::array<Eigen::Vector2d, kNumRays> relative_directions_;  ///< (cos, sin) of ray angles
};

/// Closeness value of a range under a transform: 1 for contact, 0 for no return.
double Closeness(double range, ClosenessTransform transform);

}  // namespace colav

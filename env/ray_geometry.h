// Analytic ray intersections for the range-finder.
#pragma once

#include <Eigen/Core>

#include "env/obstacles.h"

namespace colav {

/// Distance along the ray origin + t*direction (|direction| = 1) to the first point of the
/// circle, 0 when the origin is inside, max_range when there is no hit within max_range.
double RayCircleDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                         const Eigen::Vector2d& center, double radius, double max_range);

/// Distance to the entry point of the convex polygon (Cyrus-Beck clipping), 0 when the origin
/// is inside, max_range when there is no hit within max_range.
double RayPolygonDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                          const ConvexPolygon& polygon, double max_range);

}  // namespace colav

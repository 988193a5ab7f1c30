// FCL shapes of the planar world: obstacles become vertical prisms through z = 0.
#pragma once

#include <fcl/geometry/shape/convex.h>
#include <fcl/math/geometry-inl.h>

#include <memory>

#include "env/obstacles.h"

namespace colav {

/// Prism height (m): any value well above the vessel sphere's diameter works.
inline constexpr double kPrismHeight = 10.0;

/// The prism of a convex polygon, vertices relative to its bounding centre (place it with
/// PlanarTransform(polygon.bound_center)).
std::shared_ptr<fcl::Convexd> FclPrism(const ConvexPolygon& polygon);

/// A pure translation to (x, y, 0).
fcl::Transform3d PlanarTransform(const Eigen::Vector2d& position);

}  // namespace colav

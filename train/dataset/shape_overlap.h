// Exact overlap tests between the shapes of a synthetic scene (circles and convex vessel hulls),
// used to reject obstacles that would intersect the sensor's safe zone or an earlier obstacle.
// Touching counts as overlapping, as shapely's `intersects` does in the reference generator.
#pragma once

#include "env/obstacles.h"
#include "env/scenario.h"

namespace colav {

bool CirclesOverlap(const CircleSpec& a, const CircleSpec& b);
bool CirclePolygonOverlap(const CircleSpec& circle, const ConvexPolygon& polygon);
/// Separating-axis test over the edge normals of both polygons.
bool PolygonsOverlap(const ConvexPolygon& a, const ConvexPolygon& b);

}  // namespace colav

#include "train/dataset/synthetic.h"

#include <algorithm>

#include "env/angles.h"
#include "env/range_finder.h"
#include "src/random.h"
#include "train/dataset/shape_overlap.h"

namespace colav {
namespace {

// Ray i of a synthetic scan points at -pi/2 + i * 2 deg from +x (the reference's radar.py), so the
// range-finder looks along heading 0 with its first ray at -pi/2.
constexpr double kSyntheticFirstRayAngle = -kPi / 2.0;

Eigen::Vector2d UniformCentre(Rng& rng, double extent) {
  return {Uniform(rng, -extent, extent), Uniform(rng, -extent, extent)};
}

// A positive Poisson(mean) size: a zero draw is redrawn.
double PositiveSize(Rng& rng, double mean) {
  std::int64_t size = 0;
  while (size == 0) size = Poisson(rng, mean);
  return static_cast<double>(size);
}

// True when the new shape touches neither the safe zone nor an obstacle of the scene.
bool Clears(const CircleSpec& circle, const SyntheticScene& scene, const CircleSpec& safe_zone) {
  if (CirclesOverlap(circle, safe_zone)) return false;
  for (const CircleSpec& other : scene.circles) {
    if (CirclesOverlap(circle, other)) return false;
  }
  for (const ConvexPolygon& vessel : scene.vessels) {
    if (CirclePolygonOverlap(circle, vessel)) return false;
  }
  return true;
}

bool Clears(const ConvexPolygon& vessel, const SyntheticScene& scene, const CircleSpec& safe_zone) {
  if (CirclePolygonOverlap(safe_zone, vessel)) return false;
  for (const CircleSpec& circle : scene.circles) {
    if (CirclePolygonOverlap(circle, vessel)) return false;
  }
  for (const ConvexPolygon& other : scene.vessels) {
    if (PolygonsOverlap(vessel, other)) return false;
  }
  return true;
}

}  // namespace

SyntheticScene SampleSyntheticScene(Rng& rng, SyntheticObstacleCounts counts,
                                    const SyntheticSceneOptions& options) {
  const CircleSpec safe_zone{Eigen::Vector2d::Zero(), options.safe_zone_radius};
  SyntheticScene scene;
  while (static_cast<int>(scene.circles.size()) < counts.circles) {
    const double radius = PositiveSize(rng, options.radius_mean);
    const CircleSpec circle{UniformCentre(rng, options.extent), radius};
    if (Clears(circle, scene, safe_zone)) scene.circles.push_back(circle);
  }
  while (static_cast<int>(scene.vessels.size()) < counts.vessels) {
    const double width = PositiveSize(rng, options.width_mean);
    const double heading = Uniform(rng, 0.0, 2.0 * kPi);
    const ConvexPolygon vessel = VesselHull(UniformCentre(rng, options.extent), width, heading);
    if (Clears(vessel, scene, safe_zone)) scene.vessels.push_back(vessel);
  }
  return scene;
}

std::array<float, kNumRays> ScanSyntheticScene(const SyntheticScene& scene) {
  static const RangeFinder range_finder(kSyntheticFirstRayAngle);
  std::vector<const ConvexPolygon*> vessels;
  for (const ConvexPolygon& vessel : scene.vessels) vessels.push_back(&vessel);
  std::array<double, kNumRays> ranges{};
  range_finder.Scan(Eigen::Vector2d::Zero(), 0.0, scene.circles, vessels, ranges.data());
  std::array<float, kNumRays> result{};
  std::transform(ranges.begin(), ranges.end(), result.begin(),
                 [](double range) { return static_cast<float>(range); });
  return result;
}

}  // namespace colav

#include "train/dataset/synthetic.h"

#include <fmt/format.h>

#include <algorithm>
#include <string>

#include "env/angles.h"
#include "env/range_finder.h"
#include "src/error.h"
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

// Draws per shape before a scene is given up: settings that leave no room for a shape (circles
// larger than the area, a safe zone covering it) would otherwise loop forever. Even a scene that
// is hard to fill needs far fewer.
constexpr int kMaxAttemptsPerShape = 100000;
// Scenes of each group sampled by RequirePlaceableShapes.
constexpr int kTrialScenes = 20;

[[noreturn]] void ThrowNoRoom(const std::string& shape, std::size_t placed, int wanted,
                              const SyntheticSceneOptions& options) {
  throw UserError(fmt::format(
      "synthetic scenes: no room for {} {} of {} after {} attempts (synthetic.radius_mean {:g}, "
      "synthetic.width_mean {:g}, synthetic.extent {:g}, synthetic.safe_zone_radius {:g})",
      shape, placed + 1, wanted, kMaxAttemptsPerShape, options.radius_mean, options.width_mean,
      options.extent, options.safe_zone_radius));
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
  int attempts = 0;
  while (static_cast<int>(scene.circles.size()) < counts.circles) {
    if (++attempts > kMaxAttemptsPerShape) {
      ThrowNoRoom("circle", scene.circles.size(), counts.circles, options);
    }
    const double radius = PositiveSize(rng, options.radius_mean);
    const CircleSpec circle{UniformCentre(rng, options.extent), radius};
    if (Clears(circle, scene, safe_zone)) {
      scene.circles.push_back(circle);
      attempts = 0;
    }
  }
  while (static_cast<int>(scene.vessels.size()) < counts.vessels) {
    if (++attempts > kMaxAttemptsPerShape) {
      ThrowNoRoom("vessel", scene.vessels.size(), counts.vessels, options);
    }
    const double width = PositiveSize(rng, options.width_mean);
    const double heading = Uniform(rng, 0.0, 2.0 * kPi);
    const ConvexPolygon vessel = VesselHull(UniformCentre(rng, options.extent), width, heading);
    if (Clears(vessel, scene, safe_zone)) {
      scene.vessels.push_back(vessel);
      attempts = 0;
    }
  }
  return scene;
}

void RequirePlaceableShapes(const SyntheticSceneOptions& options) {
  Rng rng = MakeRng(0, "dataset.synthetic.trial");
  for (const ScanGroup group : kSyntheticGroups) {
    for (int k = 0; k < kTrialScenes; ++k) {
      SampleSyntheticScene(rng, ObstacleCountsOf(group), options);
    }
  }
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

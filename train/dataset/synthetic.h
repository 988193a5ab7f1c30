// Synthetic range scans (reference-learning 5, after Meyer 2020): random circles and vessel hulls
// around a sensor at the origin, outside a safe zone and not overlapping each other, scanned by
// 180 rays with ray i at angle 2 pi i / 180 - pi / 2 from the +x axis.
#pragma once

#include <array>
#include <vector>

#include "env/environment_spec.h"
#include "env/obstacles.h"
#include "env/scenario.h"
#include "src/seeding.h"
#include "train/dataset/scan_group.h"

namespace colav {

struct SyntheticSceneOptions {
  double radius_mean = 25.0;       ///< Poisson mean of a circle's radius (m)
  double width_mean = 10.0;        ///< Poisson mean of a vessel's width (m)
  double extent = 150.0;           ///< centres uniform in [-extent, extent]^2 (m)
  double safe_zone_radius = 10.0;  ///< no obstacle may touch this disc around the sensor (m)
};

struct SyntheticScene {
  std::vector<CircleSpec> circles;
  std::vector<ConvexPolygon> vessels;
};

/// Draws circles first, then vessels, each by rejection until it clears the safe zone and every
/// obstacle placed before it. A size of 0 (a Poisson draw of zero) is redrawn: it has no shape. A
/// shape not placed after 100,000 draws is a UserError naming the synthetic.* settings.
SyntheticScene SampleSyntheticScene(Rng& rng, SyntheticObstacleCounts counts,
                                    const SyntheticSceneOptions& options);

/// Samples a few scenes of every synthetic group (a fixed seed, nothing recorded), so that
/// settings leaving no room for the shapes fail before any work, as SampleSyntheticScene would.
void RequirePlaceableShapes(const SyntheticSceneOptions& options);

/// The ranges (m, 150 = no return) of the scene seen from the origin.
std::array<float, kNumRays> ScanSyntheticScene(const SyntheticScene& scene);

}  // namespace colav

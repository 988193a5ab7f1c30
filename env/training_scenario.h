// The paper's training environment (reference "MovingObstaclesNoRules", reference-simulator
// 4.1, 5.1-5.2, 8.2): a random path through the origin, 17 moving vessels and 11 circles.
#pragma once

#include <cstdint>

#include "env/scenario.h"

namespace colav {

struct TrainingScenarioConfig {
  double nominal_path_length = 300.0;  ///< m, start and end 150 m from the origin
  int num_moving = 17;
  double moving_displacement_sd = 500.0;  ///< m, lateral offset from the path
  double moving_width_mean = 10.0;        ///< Poisson mean of the hull width (m)
  int num_static = 11;
  double static_displacement_sd = 250.0;
  double static_radius_mean = 30.0;  ///< Poisson mean of the radius (m)
  double start_offset = 25.0;        ///< m, uniform start offset per axis
  double min_clearance = 100.0;      ///< m, from the start and the goal
  /// Bends of the path (waypoints between start, origin and end, each side): 0 draws 1 or 2 per
  /// episode (our default); 1 or 2 fixes them, as in each of the authors' training worlds, whose
  /// number of waypoints was drawn once when the world was built (reference-simulator 8.3).
  int path_bends = 0;
};

class TrainingScenarioGenerator : public ScenarioSource {
 public:
  explicit TrainingScenarioGenerator(TrainingScenarioConfig config = {}) : config_(config) {}
  Scenario Make(std::uint64_t seed) const override;

 private:
  TrainingScenarioConfig config_;
};

/// Speed (m/s) of a moving obstacle drawn from the reference's empirical table (Appendix A)
/// with the uniform number u in [0, 1).
double MovingObstacleSpeed(double u);

}  // namespace colav

// The scripted pilot that drives the vessel while simulator scans are recorded (the paper drove
// by hand; spec README "data"). It follows the path by line-of-sight steering toward the
// look-ahead point, a1 = clip(k * heading_error - kd * r + noise), with a thrust level that changes
// now and then, and occasionally turns hard for a while, so the vessel meets obstacles at every
// distance and bearing, sometimes colliding.
#pragma once

#include <array>

#include "env/environment_spec.h"
#include "env/world.h"
#include "src/seeding.h"

namespace colav {

struct ScriptedPilotOptions {
  double heading_gain = 1.0;       ///< k: yaw action per radian of heading error
  double yaw_rate_gain = 5.0;      ///< kd: yaw action per rad/s of yaw rate (damping)
  double steering_noise_sd = 0.2;  ///< Gaussian noise added to the yaw action every step
  double thrust_min = -0.2;        ///< thrust action levels are uniform in [min, max]
  double thrust_max = 1.0;
  double thrust_change_probability = 0.02;  ///< per step: draw a new thrust level
  double evasive_turn_probability = 0.01;   ///< per step: start a full-rudder turn
  int evasive_turn_min_steps = 10;
  int evasive_turn_max_steps = 40;
};

class ScriptedPilot {
 public:
  ScriptedPilot(const ScriptedPilotOptions& options, Rng rng);

  /// The action [thrust, yaw] in [-1, 1] for the world's current state.
  std::array<double, kActionSize> Act(const World& world);

 private:
  double SteeringAction(const World& world);

  ScriptedPilotOptions options_;
  Rng rng_;
  double thrust_;
  int turn_steps_left_ = 0;
  double turn_direction_ = 1.0;
};

}  // namespace colav

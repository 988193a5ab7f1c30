#include "train/dataset/pilot.h"

#include <algorithm>

#include "src/random.h"

namespace colav {

ScriptedPilot::ScriptedPilot(const ScriptedPilotOptions& options, Rng rng)
    : options_(options),
      rng_(rng),
      thrust_(Uniform(rng_, options.thrust_min, options.thrust_max)) {}

std::array<double, kActionSize> ScriptedPilot::Act(const World& world) {
  if (Uniform01(rng_) < options_.thrust_change_probability) {
    thrust_ = Uniform(rng_, options_.thrust_min, options_.thrust_max);
  }
  return {thrust_, SteeringAction(world)};
}

double ScriptedPilot::SteeringAction(const World& world) {
  if (turn_steps_left_ == 0 && Uniform01(rng_) < options_.evasive_turn_probability) {
    turn_steps_left_ =
        options_.evasive_turn_min_steps +
        static_cast<int>(UniformIndex(
            rng_, options_.evasive_turn_max_steps - options_.evasive_turn_min_steps + 1));
    turn_direction_ = Uniform01(rng_) < 0.5 ? -1.0 : 1.0;
  }
  if (turn_steps_left_ > 0) {
    --turn_steps_left_;
    return turn_direction_;
  }
  const double yaw_rate = world.vessel()[5];
  const double steering = options_.heading_gain * world.navigation().heading_error -
                          options_.yaw_rate_gain * yaw_rate +
                          Normal(rng_, 0.0, options_.steering_noise_sd);
  return std::clamp(steering, -1.0, 1.0);
}

}  // namespace colav

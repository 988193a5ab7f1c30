// The path-following reward of the training environment (reference-simulator 7.2).
#pragma once

#include <cmath>

namespace colav {

/// Reward of a step that ends in collision.
inline constexpr double kCollisionReward = -1000.0;

/// (speed/0.57) (1 + cos heading_error) / (1 + |cte|/100) - 1, or kCollisionReward.
inline double PathReward(double speed, double heading_error, double cross_track_error,
                         bool collision) {
  constexpr double kMaxSpeed = 0.57;   // m/s, the reference's 'realistic' max speed
  constexpr double kCteScale = 100.0;  // m, the observation's cte scaling
  constexpr double kLivingPenalty = 1.0;
  if (collision) return kCollisionReward;
  return (speed / kMaxSpeed) * (1.0 + std::cos(heading_error)) /
             (1.0 + std::fabs(cross_track_error) / kCteScale) -
         kLivingPenalty;
}

}  // namespace colav

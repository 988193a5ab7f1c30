// Angle helpers shared by the simulator.
#pragma once

#include <cmath>

namespace colav {

inline constexpr double kPi = 3.14159265358979323846;

/// Wraps an angle to [-pi, pi) with a floor modulo, exactly as the reference's `princip`.
inline double WrapAngle(double angle) {
  constexpr double kTwoPi = 2.0 * kPi;
  const double shifted = angle + kPi;
  return shifted - kTwoPi * std::floor(shifted / kTwoPi) - kPi;
}

}  // namespace colav

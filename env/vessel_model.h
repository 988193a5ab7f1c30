// Cybership II 3-DOF surface-vessel model (reference-simulator 3): constants, equations of
// motion and the fixed-step RKF45 integrator.
#pragma once

#include <Eigen/Core>

namespace colav {

/// Vessel state [x, y, psi, u, v, r]: world position (m), heading (rad), body-frame surge and
/// sway speed (m/s) and yaw rate (rad/s).
using VesselState = Eigen::Matrix<double, 6, 1>;
/// Generalised force [surge force (N), sway force (N), yaw moment (N m)].
using GeneralisedForce = Eigen::Vector3d;

/// Constant description of the Cybership II model.
struct CybershipModel {
  static constexpr double kMaxThrust = 2.0;   ///< N, forward only
  static constexpr double kMaxMoment = 0.15;  ///< N m
  static constexpr double kRadius = 1.255;    ///< m, collision disc ("vessel_width")
  static constexpr double kMaxSpeed = 0.57;   ///< m/s, reward normalisation

  /// Forces of an agent action a in [-1, 1]^2 (clipped): thrust (a0+1)/2 * 2 N, moment
  /// a1 * 0.15 N m; a NaN component makes the whole action zero, as in the reference.
  static GeneralisedForce ForceFromAction(double thrust_action, double moment_action);

  /// State derivative under a constant force.
  static VesselState Derivative(const VesselState& state, const GeneralisedForce& tau);

  /// One Runge-Kutta-Fehlberg 4(5) step of length h, 5th-order result, heading wrapped.
  static VesselState Step(const VesselState& state, const GeneralisedForce& tau, double h);
};

}  // namespace colav

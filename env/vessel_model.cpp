#include "env/vessel_model.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "env/angles.h"

namespace colav {
namespace {

// Rigid-body and added-mass parameters [constants.py:4-11].
constexpr double kMass = 23.8;
constexpr double kXg = 0.046;
constexpr double kIz = 1.760;
constexpr double kXudot = -2.0;
constexpr double kYvdot = -10.0;
constexpr double kYrdot = 0.0;
constexpr double kNrdot = -1.0;
constexpr double kNvdot = 0.0;
// Damping coefficients [constants.py:12-25, 34].
constexpr double kXu = -0.7225;
constexpr double kYv = -0.8612;
constexpr double kYr = 0.1079;
constexpr double kNv = 0.1052;
constexpr double kNr = -0.5;
constexpr double kXuu = -1.3274;
constexpr double kYvv = -36.2823;
constexpr double kYrr = -0.02;
constexpr double kYrv = -0.01;
constexpr double kYvr = -0.01;
constexpr double kNvv = 5.0437;
constexpr double kNrr = 0.005;
constexpr double kNrv = -0.001;
constexpr double kNvr = -0.001;
constexpr double kXuuu = -5.8664;

// M = [[m - X_udot, 0, 0], [0, m - Y_vdot, m x_g - Y_rdot], [0, m x_g - N_vdot, I_z - N_rdot]].
constexpr double kM11 = kMass - kXudot;
constexpr double kM23 = kMass * kXg - kYrdot;

const Eigen::Matrix3d& InverseMassMatrix() {
  static const Eigen::Matrix3d inverse = [] {
    Eigen::Matrix3d m;
    m << kM11, 0.0, 0.0,                            //
        0.0, kMass - kYvdot, kMass * kXg - kYrdot,  //
        0.0, kMass * kXg - kNvdot, kIz - kNrdot;
    return Eigen::Matrix3d(m.inverse());
  }();
  return inverse;
}

}  // namespace

GeneralisedForce CybershipModel::ForceFromAction(double thrust_action, double moment_action) {
  if (std::isnan(thrust_action) || std::isnan(moment_action)) return GeneralisedForce::Zero();
  const double a0 = (std::clamp(thrust_action, -1.0, 1.0) + 1.0) / 2.0;
  const double a1 = std::clamp(moment_action, -1.0, 1.0);
  return {a0 * kMaxThrust, 0.0, a1 * kMaxMoment};
}

VesselState CybershipModel::Derivative(const VesselState& s, const GeneralisedForce& tau) {
  const double psi = s[2];
  const double u = s[3];
  const double v = s[4];
  const double r = s[5];
  const double c = std::cos(psi);
  const double sn = std::sin(psi);
  // Coriolis C(nu) nu; the reference uses m11 (not m22) in c13 [constants.py:56-69].
  const Eigen::Vector3d coriolis(-kM11 * v * r - kM23 * r * r, kM11 * u * r, kM23 * u * r);
  const double d11 = -kXu - kXuu * std::fabs(u) - kXuuu * u * u;
  const double d22 = -kYv - kYvv * std::fabs(v) - kYrv * std::fabs(r);
  const double d23 = -kYr - kYvr * std::fabs(v) - kYrr * std::fabs(r);
  const double d32 = -kNv - kNvv * std::fabs(v) - kNrv * std::fabs(r);
  const double d33 = -kNr - kNvr * std::fabs(v) - kNrr * std::fabs(r);
  const Eigen::Vector3d damping(d11 * u, d22 * v + d23 * r, d32 * v + d33 * r);
  const Eigen::Vector3d nu_dot = InverseMassMatrix() * (tau - damping - coriolis);
  VesselState derivative;
  derivative << c * u - sn * v, sn * u + c * v, r, nu_dot;
  return derivative;
}

VesselState CybershipModel::Step(const VesselState& s, const GeneralisedForce& tau, double h) {
  const VesselState k1 = Derivative(s, tau);
  const VesselState k2 = Derivative(s + h * k1 / 4.0, tau);
  const VesselState k3 = Derivative(s + 3.0 * h * k1 / 32.0 + 9.0 * h * k2 / 32.0, tau);
  const VesselState k4 = Derivative(
      s + 1932.0 * h * k1 / 2197.0 - 7200.0 * h * k2 / 2197.0 + 7296.0 * h * k3 / 2197.0, tau);
  const VesselState k5 = Derivative(
      s + 439.0 * h * k1 / 216.0 - 8.0 * h * k2 + 3680.0 * h * k3 / 513.0 - 845.0 * h * k4 / 4104.0,
      tau);
  const VesselState k6 =
      Derivative(s - 8.0 * h * k1 / 27.0 + 2.0 * h * k2 - 3544.0 * h * k3 / 2565.0 +
                     1859.0 * h * k4 / 4104.0 - 11.0 * h * k5 / 40.0,
                 tau);
  VesselState next = s + h * (16.0 * k1 / 135.0 + 6656.0 * k3 / 12825.0 + 28561.0 * k4 / 56430.0 -
                              9.0 * k5 / 50.0 + 2.0 * k6 / 55.0);
  next[2] = WrapAngle(next[2]);
  return next;
}

}  // namespace colav

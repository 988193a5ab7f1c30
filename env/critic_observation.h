// What a privileged critic sees beside the policy's observation (asymmetric actor-critic, Pinto
// et al. 2017): the true motion of the moving vessels nearest to the agent's, which one range
// scan cannot show. Only training reads it (train_ppo's policy.critic_vessels); the policy acts
// on the range-finder and navigation values alone, and the test never computes it.
//
// For each of the `vessels` nearest moving obstacles (centre to centre, nearest first) within
// kCriticVesselRange, kCriticValuesPerVessel values in the agent's body frame (x along its surge
// axis, y along its sway axis, as the navigation values' u and v):
//   [1 (present), x / 150 m, y / 150 m, (relative velocity x, y) / 0.57 m/s, width / 10 m],
// the relative velocity being the obstacle's minus the agent's; slots beyond the vessels in range
// are all 0. 150 m is the range-finder's reach, 0.57 m/s the agent's speed normalisation
// (CybershipModel::kMaxSpeed).
#pragma once

namespace colav {

class World;

inline constexpr int kCriticValuesPerVessel = 6;
/// Obstacles farther than this (m, centre to centre) are left out: twice the range-finder's reach.
inline constexpr double kCriticVesselRange = 300.0;

/// Floats of the critic's observation of `vessels` vessels.
constexpr int CriticObservationSize(int vessels) { return vessels * kCriticValuesPerVessel; }

/// Writes CriticObservationSize(vessels) floats of `world`'s current state to `out`.
void WriteCriticObservation(const World& world, int vessels, float* out);

}  // namespace colav

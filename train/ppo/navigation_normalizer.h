// Navigation normalisation: Stable-Baselines3's VecNormalize(norm_obs=True) on the 6 navigation
// values of the observation only. The policy sees (x - mean) / sqrt(var + 1e-8) per value, with
// the running mean and variance of every observation collected so far (SB3's RunningMeanStd, one
// estimate for all worlds); the range scans are left alone, since a pre-trained encoder expects
// its closeness values. Unlike SB3 the values are not clipped to +-10, so the exported policy
// (policy_export.h) applies the same affine map to raw observations.
//
// Why: the navigation values differ in spread by a factor of 20 (a trained agent's surge speed
// varies by 0.05 m/s, its yaw rate by 0.05 rad/s, its heading errors by 0.7-1 rad), so the
// policy's first layer barely sees its own speed and turn at the paper's initialisation.
#pragma once

#include <array>
#include <vector>

#include "env/environment_spec.h"
#include "models/policy_export.h"
#include "train/ppo/running_variance.h"

namespace colav {

class NavigationNormalizer {
 public:
  static constexpr double kEpsilon = 1e-8;  ///< SB3's
  using Moments = std::array<RunningVariance, kNavigationSize>;

  /// Adds the navigation values of `rows` observations, `stride` floats apart, to the moments.
  void Update(const float* observations, int rows, int stride);
  /// Replaces the navigation values of `rows` observations by their normalised values.
  void Normalize(float* observations, int rows, int stride) const;
  /// The float mean and spread Normalize applies: (x - mean) / spread.
  NavigationNormalization Normalization() const;

  const Moments& moments() const { return moments_; }
  void Restore(const Moments& moments) { moments_ = moments; }

 private:
  Moments moments_;
  std::vector<double> column_;  // scratch: one navigation value of every row
};

}  // namespace colav

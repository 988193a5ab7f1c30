// A running mean and variance, as Stable-Baselines3's RunningMeanStd: what reward scaling
// (reward_scaling.h) and navigation normalisation (navigation_normalizer.h) divide by.
#pragma once

#include <vector>

namespace colav {

/// A running mean and (population) variance, merged batch by batch with Chan et al.'s parallel
/// formula, as SB3's RunningMeanStd; it starts as mean 0, variance 1 with a weight of 1e-4.
struct RunningVariance {
  double mean = 0.0;
  double variance = 1.0;
  double count = 1e-4;

  void Update(const std::vector<double>& batch);
};

}  // namespace colav

#include "train/ppo/navigation_normalizer.h"

#include <cmath>

namespace colav {

void NavigationNormalizer::Update(const float* observations, int rows, int stride) {
  column_.resize(rows);
  for (int j = 0; j < kNavigationSize; ++j) {
    for (int row = 0; row < rows; ++row) {
      column_[row] = observations[static_cast<std::ptrdiff_t>(row) * stride + j];
    }
    moments_[j].Update(column_);
  }
}

NavigationNormalization NavigationNormalizer::Normalization() const {
  NavigationNormalization normalization;
  for (int j = 0; j < kNavigationSize; ++j) {
    normalization.mean[j] = static_cast<float>(moments_[j].mean);
    normalization.spread[j] = static_cast<float>(std::sqrt(moments_[j].variance + kEpsilon));
  }
  return normalization;
}

void NavigationNormalizer::Normalize(float* observations, int rows, int stride) const {
  const NavigationNormalization normalization = Normalization();
  for (int row = 0; row < rows; ++row) {
    float* navigation = observations + static_cast<std::ptrdiff_t>(row) * stride;
    for (int j = 0; j < kNavigationSize; ++j) {
      // As the exported policy computes it: float subtraction, then float division.
      navigation[j] = (navigation[j] - normalization.mean[j]) / normalization.spread[j];
    }
  }
}

}  // namespace colav

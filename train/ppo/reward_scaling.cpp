#include "train/ppo/reward_scaling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace colav {

RewardScaler::RewardScaler(int num_envs, double gamma) : gamma_(gamma) {
  state_.returns.assign(num_envs, 0.0);
}

void RewardScaler::Scale(const float* rewards, const std::uint8_t* dones, float* scaled) {
  std::vector<double>& returns = state_.returns;
  for (std::size_t e = 0; e < returns.size(); ++e) returns[e] = returns[e] * gamma_ + rewards[e];
  state_.return_variance.Update(returns);
  const double scale = 1.0 / std::sqrt(state_.return_variance.variance + kEpsilon);
  for (std::size_t e = 0; e < returns.size(); ++e) {
    scaled[e] = static_cast<float>(std::clamp(rewards[e] * scale, -kClip, kClip));
    if (dones[e] != 0) returns[e] = 0.0;
  }
}

void RewardScaler::Restore(const RewardScalingState& state) {
  if (state.returns.size() != state_.returns.size()) {
    throw std::invalid_argument("reward scaling recorded for " +
                                std::to_string(state.returns.size()) + " worlds, not " +
                                std::to_string(state_.returns.size()));
  }
  state_ = state;
}

void RewardScaler::RestartReturns() {
  std::fill(state_.returns.begin(), state_.returns.end(), 0.0);
}

}  // namespace colav

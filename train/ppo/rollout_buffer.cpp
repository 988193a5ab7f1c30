#include "train/ppo/rollout_buffer.h"

#include <limits>

#include "train/ppo/gae.h"

namespace colav {

RolloutBuffer::RolloutBuffer(int num_steps, int num_envs, int observation_size, int state_size,
                             int critic_observation_size)
    : num_steps_(num_steps),
      num_envs_(num_envs),
      observation_size_(observation_size),
      state_size_(state_size),
      critic_observation_size_(critic_observation_size),
      observations_(static_cast<std::size_t>(size()) * observation_size),
      actions_(static_cast<std::size_t>(size()) * kActionSize),
      log_probs_(size()),
      values_(size()),
      rewards_(size()),
      final_values_(size()),
      dones_(size()),
      bootstrapped_(size()),
      last_values_(num_envs),
      advantages_(size()),
      returns_(size()),
      states_(static_cast<std::size_t>(size()) * state_size),
      critic_observations_(static_cast<std::size_t>(size()) * critic_observation_size) {}

void RolloutBuffer::ComputeReturnsAndAdvantages(double gamma, double lambda) {
  GaeInput input;
  input.num_steps = num_steps_;
  input.num_envs = num_envs_;
  input.gamma = gamma;
  input.lambda = lambda;
  input.rewards = rewards_.data();
  input.values = values_.data();
  input.dones = dones_.data();
  input.bootstrapped = bootstrapped_.data();
  input.final_values = final_values_.data();
  input.last_values = last_values_.data();
  ComputeGae(input, advantages_.data(), returns_.data());
}

double RolloutBuffer::ExplainedVariance() const {
  double return_mean = 0.0, error_mean = 0.0;
  for (int i = 0; i < size(); ++i) {
    return_mean += returns_[i];
    error_mean += returns_[i] - values_[i];
  }
  return_mean /= size();
  error_mean /= size();
  double return_variance = 0.0, error_variance = 0.0;
  for (int i = 0; i < size(); ++i) {
    return_variance += (returns_[i] - return_mean) * (returns_[i] - return_mean);
    const double error = returns_[i] - values_[i] - error_mean;
    error_variance += error * error;
  }
  if (return_variance == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return 1.0 - error_variance / return_variance;
}

}  // namespace colav

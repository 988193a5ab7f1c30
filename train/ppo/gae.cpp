#include "train/ppo/gae.h"

namespace colav {

void ComputeGae(const GaeInput& in, float* advantages, float* returns) {
  const int N = in.num_envs;
  for (int env = 0; env < N; ++env) {
    double last_advantage = 0.0;
    for (int t = in.num_steps - 1; t >= 0; --t) {
      const int i = t * N + env;
      double reward = in.rewards[i];
      if (in.bootstrapped[i]) reward += in.gamma * in.final_values[i];
      const double next_value = t + 1 < in.num_steps ? in.values[i + N] : in.last_values[env];
      const double next_non_terminal = in.dones[i] ? 0.0 : 1.0;
      const double delta = reward + in.gamma * next_value * next_non_terminal - in.values[i];
      last_advantage = delta + in.gamma * in.lambda * next_non_terminal * last_advantage;
      advantages[i] = static_cast<float>(last_advantage);
      returns[i] = static_cast<float>(last_advantage + in.values[i]);
    }
  }
}

}  // namespace colav

#include "train/ppo/gae.h"

#include <gtest/gtest.h>

#include <vector>

namespace colav {
namespace {

// Two worlds, four steps, gamma 0.9, lambda 0.8, written step-major (t * 2 + env).
// World 0: an episode terminates at t = 1 and one is truncated at t = 2 (final value 3).
// World 1: no episode ends; its final_values are garbage that must be ignored.
TEST(GaeTest, HandComputedRolloutWithATerminationAndATruncation) {
  const std::vector<float> rewards = {1, 0, 2, 0, 0.5f, 0, 1, 1};
  const std::vector<float> values = {0.5f, 0, 1.0f, 0, 0.2f, 0, 0.4f, 0};
  const std::vector<std::uint8_t> dones = {0, 0, 1, 0, 1, 0, 0, 0};
  const std::vector<std::uint8_t> truncated = {0, 0, 0, 0, 1, 0, 0, 0};
  const std::vector<float> final_values = {99, 99, 99, 99, 3.0f, 99, 99, 99};
  const std::vector<float> last_values = {2.0f, 0.0f};
  GaeInput input;
  input.num_steps = 4;
  input.num_envs = 2;
  input.gamma = 0.9;
  input.lambda = 0.8;
  input.rewards = rewards.data();
  input.values = values.data();
  input.dones = dones.data();
  input.bootstrapped = truncated.data();
  input.final_values = final_values.data();
  input.last_values = last_values.data();
  std::vector<float> advantages(8), returns(8);
  ComputeGae(input, advantages.data(), returns.data());

  // World 0, backwards:
  //   t=3: delta = 1 + 0.9 * 2.0 - 0.4 = 2.4                   A = 2.4
  //   t=2: truncated, r = 0.5 + 0.9 * 3.0 = 3.2; delta = 3.2 - 0.2 = 3.0, no carry: A = 3.0
  //   t=1: terminated, no bootstrap: delta = 2 - 1 = 1.0       A = 1.0
  //   t=0: delta = 1 + 0.9 * 1.0 - 0.5 = 1.4; A = 1.4 + 0.9 * 0.8 * 1.0 = 2.12
  // World 1: A3 = 1, then A = 0.72 A_next: 0.72, 0.5184, 0.373248.
  const std::vector<float> expected_advantages = {2.12f, 0.373248f, 1.0f, 0.5184f,
                                                  3.0f,  0.72f,     2.4f, 1.0f};
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(advantages[i], expected_advantages[i], 1e-5) << i;
    EXPECT_NEAR(returns[i], expected_advantages[i] + values[i], 1e-5) << i;
  }
}

}  // namespace
}  // namespace colav

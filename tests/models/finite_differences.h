// Gradient check in double precision: the analytic gradients of a function (through autograd and
// the custom backward passes under test) against central finite differences, entry by entry.
#pragma once

#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace colav::testing {

// Checks d/d inputs of sum(function(inputs) * w) for a fixed random w, for every entry of every
// input (float64 tensors, requiring grad). `names` label the inputs in failure messages.
inline void ExpectGradientsMatchFiniteDifferences(
    const std::function<torch::Tensor(const std::vector<torch::Tensor>&)>& function,
    std::vector<torch::Tensor> inputs, const std::vector<std::string>& names) {
  constexpr double kStep = 1e-6;
  constexpr double kTolerance = 1e-6;
  const torch::Tensor output_weights = torch::randn_like(function(inputs));
  const auto loss = [&] { return (function(inputs) * output_weights).sum(); };
  const std::vector<torch::Tensor> analytic = torch::autograd::grad({loss()}, inputs);

  torch::NoGradGuard no_grad;
  for (std::size_t input = 0; input < inputs.size(); ++input) {
    ASSERT_EQ(analytic[input].sizes(), inputs[input].sizes()) << names[input];
    const torch::Tensor flat = inputs[input].view(-1);
    const torch::Tensor flat_gradient = analytic[input].reshape(-1);
    for (std::int64_t i = 0; i < flat.numel(); ++i) {
      const double original = flat[i].item<double>();
      flat[i] = original + kStep;
      const double plus = loss().item<double>();
      flat[i] = original - kStep;
      const double minus = loss().item<double>();
      flat[i] = original;
      EXPECT_NEAR(flat_gradient[i].item<double>(), (plus - minus) / (2 * kStep), kTolerance)
          << names[input] << "[" << i << "]";
    }
  }
}

}  // namespace colav::testing

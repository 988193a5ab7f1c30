// Tiny TorchScript policies made in the tests (no trained agent needed).
#pragma once

#include <torch/script.h>
#include <torch/torch.h>

#include <filesystem>
#include <string>

namespace colav::testing_policies {

/// A module whose methods are `source` (TorchScript), with an optional parameter `weight`.
inline torch::jit::Module ScriptedModule(const std::string& source,
                                         const torch::Tensor& weight = {}) {
  torch::jit::Module module("TestPolicy");
  if (weight.defined()) module.register_parameter("weight", weight, /*is_buffer=*/false);
  module.define(source);
  return module;
}

/// Full thrust, rudder amidships, whatever it observes.
inline torch::jit::Module ConstantThrustPolicy() {
  return ScriptedModule(R"(
def forward(self, obs: Tensor) -> Tensor:
    thrust = torch.ones_like(obs[:, 0:1])
    return torch.cat([thrust, torch.zeros_like(thrust)], 1)
)");
}

/// tanh(obs @ W) with a fixed random W [186, 2] of the given seed: a policy that reacts to every
/// observation value, so a mixed-up observation row changes the episode.
inline torch::jit::Module ReactivePolicy(std::uint64_t seed) {
  torch::manual_seed(seed);
  return ScriptedModule(R"(
def forward(self, obs: Tensor) -> Tensor:
    return torch.tanh(torch.matmul(obs, self.weight) + torch.tensor([0.8, 0.0]))
)",
                        0.3 * torch::randn({186, 2}));
}

/// Built for a 180-value observation: forward on [B, 186] fails.
inline torch::jit::Module WrongObservationSizePolicy() {
  return ScriptedModule(R"(
def forward(self, obs: Tensor) -> Tensor:
    return torch.matmul(obs, self.weight)
)",
                        torch::zeros({180, 2}));
}

/// Returns three action values per observation.
inline torch::jit::Module WrongActionSizePolicy() {
  return ScriptedModule(R"(
def forward(self, obs: Tensor) -> Tensor:
    return obs[:, 0:3]
)");
}

inline std::filesystem::path SavePolicy(torch::jit::Module module,
                                        const std::filesystem::path& path) {
  module.save(path.string());
  return path;
}

}  // namespace colav::testing_policies

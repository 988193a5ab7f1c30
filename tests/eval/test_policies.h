// Tiny TorchScript policies made in the tests (no trained agent needed).
#pragma once

#include <torch/script.h>
#include <torch/torch.h>

#include <cstdint>
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

/// A recurrent policy (attribute recurrent_size = `size`) whose methods are `source`.
inline torch::jit::Module RecurrentModule(const std::string& source, std::int64_t size,
                                          const torch::Tensor& weight = {}) {
  torch::jit::Module module = ScriptedModule(source, weight);
  module.register_attribute("recurrent_size", c10::IntType::get(), size);
  return module;
}

/// A recurrent ReactivePolicy: (action, next state) from tanh([obs, state] @ W) with a fixed
/// random W [186 + 3, 2 + 3] of the given seed, so an action depends on the whole episode so far.
inline torch::jit::Module RecurrentReactivePolicy(std::uint64_t seed) {
  torch::manual_seed(seed);
  return RecurrentModule(R"(
def initial_state(self, batch: int) -> Tensor:
    return torch.zeros([batch, 3])
def step(self, obs: Tensor, state: Tensor) -> Tuple[Tensor, Tensor]:
    z = torch.matmul(torch.cat([obs, state], 1), self.weight)
    return torch.tanh(z[:, 0:2] + torch.tensor([0.8, 0.0])), torch.tanh(z[:, 2:5])
)",
                         3, 0.3 * torch::randn({189, 5}));
}

/// A recurrent policy whose step returns next states of 4 values for its states of 3.
inline torch::jit::Module WrongStateSizePolicy() {
  return RecurrentModule(R"(
def initial_state(self, batch: int) -> Tensor:
    return torch.zeros([batch, 3])
def step(self, obs: Tensor, state: Tensor) -> Tuple[Tensor, Tensor]:
    return obs[:, 0:2], obs[:, 0:4]
)",
                         3);
}

inline std::filesystem::path SavePolicy(torch::jit::Module module,
                                        const std::filesystem::path& path) {
  module.save(path.string());
  return path;
}

}  // namespace colav::testing_policies

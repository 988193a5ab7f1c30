// TorchScript export of the trained policy, written without Python (spec interfaces.md): the
// ActorCritic's parameters are copied into a torch::jit::Module whose methods are compiled from
// TorchScript source generated here, so policy.pt loads with torch.jit.load in Python and
// torch::jit::load in C++.
//
//   forward(obs: float32 [B, 6 + 180 * scans]) -> action [B, 2]: the Gaussian's mean clipped to
//                                     [-1, 1], or its tanh for a policy trained with squashed
//                                     actions (policy.squash_actions): the deterministic action;
//                                     with deterministic_std_scale c (policy.deterministic_*), per
//                                     action E[clip(u, -1, 1)], u ~ N(mean, (c * std)^2), through
//                                     expected_clipped_action(mean) and the buffer
//                                     deterministic_std [2] (c times the trained std);
//   value(obs) -> [B, 1] (none for a privileged critic, ActorCriticOptions::critic_vessels > 0,
//   whose value also read what only training computes);  features(obs) -> [B, 6 + scans * P]
//   (the extractor's output, [B, 18] for one scan and the paper's extractors).
//   Observation layout: indices 0-5 navigation [u, v, r, cte/100, heading error, look-ahead
//   heading error], 6-185 the 180 closeness values (ray i at -pi + (i+1) * 2 degrees), then the
//   earlier scans' 180 values each, newest first, when scans > 1.
//   A policy trained with navigation normalisation (ppo.normalize_navigation) holds buffers
//   navigation_mean and navigation_spread [6] and its features(obs) start with
//   (obs[:, 0:6] - navigation_mean) / navigation_spread: forward and value take raw observations.
//   Attributes: extractor (str), locked (bool), scans (int, range scans per observation),
//   global_step (int), observation_layout (str, the line above for the closeness transform trained
//   with), observation_settings (str, the settings trained with,
//   models/observation_settings_record.h).
// A recurrent policy (ActorCriticOptions::recurrent_size H > 0) also has the attribute
// recurrent_size (int, H; memoryless policies have none) and acts through its state instead:
//   initial_state(batch: int) -> zeros float32 [batch, H], the state at an episode's start;
//   step(obs, state [B, H]) -> Tuple[action [B, 2], next state [B, H]], the action as forward's;
//   step_value(obs, state) -> Tuple[value [B, 1], next state [B, H]] (none for a privileged
//   critic);  features(obs) as above.
//   A critic with a memory of its own (ActorCriticOptions::separate_critic_memory) steps it in
//   step_value, through critic_recurrent_cell: its state is kept apart from step's.
//   Its forward(obs) fails with "AssertionError: recurrent policy: call step(obs, state) starting
//   from initial_state(B)" (acting from a zero state at every step would be a different, worse
//   policy) and it has no value(obs). The GRU cell is recurrent_cell(x, state).
// A parameter `a.b.c` of the ActorCritic is the attribute `a_b_c` of the scripted module.
#pragma once

#include <torch/script.h>
#include <torch/torch.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>

#include "env/environment_spec.h"
#include "env/observation_settings.h"
#include "models/actor_critic.h"

namespace colav {

/// The map a policy trained with navigation normalisation applies to the 6 navigation values
/// before anything else: (x - mean) / spread, in float (train/ppo/navigation_normalizer.h).
struct NavigationNormalization {
  std::array<float, kNavigationSize> mean{};
  std::array<float, kNavigationSize> spread{};
};

/// The scripted policy in memory (parameters are detached copies), recording the observation
/// `settings` it was trained with; with `navigation`, a model trained on normalised navigation
/// values becomes a policy of raw observations.
torch::jit::Module ScriptPolicy(ActorCriticImpl& model, std::int64_t global_step,
                                const ObservationSettings& settings,
                                const std::optional<NavigationNormalization>& navigation = {});

/// Writes ScriptPolicy(...) to `path` atomically; an unwritable path is a UserError naming it.
void ExportPolicy(ActorCriticImpl& model, std::int64_t global_step,
                  const ObservationSettings& settings, const std::filesystem::path& path,
                  const std::optional<NavigationNormalization>& navigation = {});

}  // namespace colav

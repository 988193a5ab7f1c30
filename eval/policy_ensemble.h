// One policy file that acts with the mean of several trained policies' deterministic actions.
// Agents trained from different seeds fail in different scenarios (README, "Ensembles of
// seeds"); averaging their actions keeps what most of them do. The members may be memoryless or
// recurrent, and of different recipes, but must share their observation settings (recorded in the
// file or its sidecar, eval/policy.h).
//
// The ensemble has the interface of a trained policy.pt (models/policy_export.h), so evaluate,
// study and colav.Policy run it:
//   only memoryless members: forward(obs) -> the mean of the members' actions, each clipped to
//                            [-1, 1] as evaluate clips it;
//   a recurrent member:      recurrent_size (the members' state sizes summed), initial_state(B)
//                            (the recurrent members' initial states side by side, in their order)
//                            and step(obs, state) -> (mean action, next state), each recurrent
//                            member stepping its own slice of the state; forward(obs) fails as a
//                            recurrent policy's does.
// Attributes: observation_settings (the members'), member_paths (their paths, one per line). The
// members are its submodules member_0, member_1, ... in the order given.
#pragma once

#include <torch/script.h>

#include <filesystem>
#include <vector>

#include "eval/policy.h"

namespace colav {

/// The ensemble of `members` (at least two), in memory. A member without observation settings, or
/// with settings other than the first member's, is a UserError naming its file.
torch::jit::Module EnsemblePolicy(const std::vector<Policy>& members);

/// Loads the policy files `members` (Policy checks each), and writes their EnsemblePolicy to `out`
/// atomically. Bad input, including `out` being one of the members, is a UserError naming it.
void WriteEnsemblePolicy(const std::vector<std::filesystem::path>& members,
                         const std::filesystem::path& out);

}  // namespace colav

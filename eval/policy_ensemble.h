// One policy file that acts with the mean of several trained policies' deterministic actions, or
// that hands the helm to one of two by the range of the nearest obstacle. Agents trained from
// different seeds fail in different scenarios (docs/results.md, "Ensembles of seeds"); averaging
// their actions keeps what most of them do. Agents of different recipes are good at different
// things: one keeps clear of obstacles, another keeps to the path (docs/results.md, "Two
// helmsmen"). The members may be memoryless or recurrent, and of different recipes, but must share
// their observation settings (recorded in the file or its sidecar, eval/policy.h). A stall rule
// (eval/stall_rule.h) hands the helm to the second member for the rest of the episode, or, with
// more members, to the next one at each stall: a vessel that stalls again under its relief is
// handed to a third member, which passes where the relief parks (docs/results.md, "A rescue at the
// second stall").
//
// The ensemble has the interface of a trained policy.pt (models/policy_export.h), so evaluate,
// study and colav.Policy run it:
//   only memoryless members: forward(obs) -> the members' actions, each clipped to [-1, 1] as
//                            evaluate clips it, combined by the EnsembleRule;
//   a recurrent member or    recurrent_size (the members' state sizes summed, plus the stall
//   a stall rule:            rule's two columns last), initial_state(B) (the recurrent members'
//                            initial states side by side, in their order) and step(obs, state)
//                            -> (action, next state), each recurrent member stepping its own
//                            slice of the state; forward(obs) fails as a recurrent policy's does.
// Every member acts at every step, whichever action the rule keeps, so a memory sees every
// observation.
// Attributes: observation_settings (the members'), member_paths (their paths, one per line). The
// members are its submodules member_0, member_1, ... in the order given.
#pragma once

#include <torch/script.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <vector>

#include "eval/policy.h"
#include "eval/stall_rule.h"

namespace colav {

/// How an ensemble combines its members' clipped actions.
struct EnsembleRule {
  /// Absent: their mean. Present: the first member's action while the newest scan's nearest
  /// return lies within this many metres (0 < m < 150), the second's otherwise; two members, or
  /// more with a stall rule (the later ones are reliefs only).
  std::optional<double> near_within_m;
  /// Present: member k (k >= 1) steers from the k-th stall of the episode on, the last member to
  /// its end; before the first stall, the first member (or, with near_within_m, the range rule).
  std::optional<StallRule> stall;
};

/// A UserError unless `members` policies can form an ensemble under `rule`.
void CheckEnsemble(std::size_t members, const EnsembleRule& rule);

/// The ensemble of `members` under `rule`, in memory. A member without observation settings, or
/// with settings other than the first member's, is a UserError naming its file.
torch::jit::Module EnsemblePolicy(const std::vector<Policy>& members, const EnsembleRule& rule);

/// Loads the policy files `members` (Policy checks each), and writes their EnsemblePolicy to `out`
/// atomically. Bad input, including `out` being one of the members, is a UserError naming it.
void WriteEnsemblePolicy(const std::vector<std::filesystem::path>& members,
                         const std::filesystem::path& out, const EnsembleRule& rule);

}  // namespace colav

// Reading a policy file's weights back into an ActorCritic (the inverse of policy_export.h's
// ScriptPolicy): train_ppo's policy.init starts a run from a trained policy.pt, or from a student
// of scripts/distill_policy.py, which writes its weights into its starting policy's file.
#pragma once

#include <filesystem>

#include "env/observation_settings.h"
#include "models/actor_critic.h"

namespace colav {

/// Copies the weights of the policy file `path` into `model`: each parameter `a.b.c` from the
/// file's parameter `a_b_c`. The file must be of the same architecture (the same extractor and
/// every parameter of the same name and shape, none left over), hold finite values, record
/// `settings` as its observation settings (or none), and not normalise its navigation values.
/// Anything else is a UserError naming the file and what differs; `model` is then unchanged.
void LoadPolicyWeights(const std::filesystem::path& path, const ObservationSettings& settings,
                       ActorCriticImpl& model);

}  // namespace colav

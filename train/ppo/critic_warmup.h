// A critic warm-up for a run that starts from a trained policy (policy.init): the first updates
// train the critic alone while the actor acts as it was given, so that the actor's first
// advantages come from a critic of its own returns rather than from the stale one it was
// started with (a distilled student's critic is its starting policy's). The actor joins with
// Adam started afresh: its moments were never fed, and its bias correction must count its own
// steps, not the critic's.
#pragma once

#include <cstdint>

namespace colav {

enum class UpdatePhase {
  kCriticOnly,  ///< the actor, its log std and everything it reads (extractor, memory) held
  kActorJoins,  ///< the first update of every parameter; Adam restarts before it
  kAll,         ///< every trainable parameter, as without a warm-up
};

/// The phase of the update after a rollout of `rollout_steps` steps that ends at `global_step`,
/// in a run whose rollouts ending at or before `warmup_steps` train the critic alone (0: none).
UpdatePhase UpdatePhaseAt(std::int64_t global_step, std::int64_t rollout_steps,
                          std::int64_t warmup_steps);

}  // namespace colav

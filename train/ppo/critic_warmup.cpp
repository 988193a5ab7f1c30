#include "train/ppo/critic_warmup.h"

namespace colav {

UpdatePhase UpdatePhaseAt(std::int64_t global_step, std::int64_t rollout_steps,
                          std::int64_t warmup_steps) {
  if (warmup_steps <= 0) return UpdatePhase::kAll;
  if (global_step <= warmup_steps) return UpdatePhase::kCriticOnly;
  // The rollout before this one ended within the warm-up.
  return global_step - rollout_steps <= warmup_steps ? UpdatePhase::kActorJoins : UpdatePhase::kAll;
}

}  // namespace colav

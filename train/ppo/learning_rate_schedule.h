// How PPO's learning rate moves over a run. Stable-Baselines3 evaluates a schedule before each
// update at "progress remaining" 1 - steps / total steps, counted after the rollout; `linear` is
// the RL Zoo's linear_schedule (initial * progress remaining), held at 0 once the run has
// collected its total (SB3's last rollout overshoots the total and would go negative).
#pragma once

#include <cstdint>
#include <string>

namespace colav {

enum class LearningRateSchedule {
  kConstant,  ///< the paper's and SB3's default
  kLinear,    ///< from the initial rate down to 0 at the run's total steps
};

LearningRateSchedule ParseLearningRateSchedule(const std::string& name);
std::string LearningRateScheduleName(LearningRateSchedule schedule);

/// The rate of the update that follows a rollout ending at `global_step` of `total_steps`.
double ScheduledLearningRate(LearningRateSchedule schedule, double initial_rate,
                             std::int64_t global_step, std::int64_t total_steps);

}  // namespace colav

#include "train/ppo/learning_rate_schedule.h"

#include <algorithm>

#include "src/error.h"

namespace colav {

LearningRateSchedule ParseLearningRateSchedule(const std::string& name) {
  if (name == "constant") return LearningRateSchedule::kConstant;
  if (name == "linear") return LearningRateSchedule::kLinear;
  throw UserError("unknown learning-rate schedule '" + name + "' (expected constant or linear)");
}

std::string LearningRateScheduleName(LearningRateSchedule schedule) {
  return schedule == LearningRateSchedule::kLinear ? "linear" : "constant";
}

double ScheduledLearningRate(LearningRateSchedule schedule, double initial_rate,
                             std::int64_t global_step, std::int64_t total_steps) {
  if (schedule == LearningRateSchedule::kConstant) return initial_rate;
  const double progress_remaining =
      1.0 - static_cast<double>(global_step) / static_cast<double>(total_steps);
  return initial_rate * std::max(0.0, progress_remaining);
}

}  // namespace colav

#include "env/environment_config.h"

namespace colav {

void AddEnvironmentKeys(ConfigSchema& schema) {
  const EnvironmentConfig defaults;
  schema
      .AddString(
          "env.closeness", "linear",
          "range -> closeness: linear 1-d/150 (paper) or log 1-ln(1+d)/ln151 (reference code)",
          {"linear", "log"})
      .AddBool("env.test_mode", defaults.test_mode,
               "switch off the cumulative-reward termination (reference test procedure)")
      .AddInt("env.max_steps", defaults.max_steps, "steps before an episode is truncated", 1,
              1000000)
      .AddDouble("env.goal_radius", defaults.goal_radius, "goal reached within this distance (m)",
                 0.0, 1000.0)
      .AddDouble("env.goal_progress", defaults.goal_progress,
                 "goal reached when progress s*/L reaches this", 0.0, 2.0)
      .AddDouble("env.min_cumulative_reward", defaults.min_cumulative_reward,
                 "training episodes end below this cumulative reward");
}

EnvironmentConfig EnvironmentConfigFrom(const Config& config) {
  EnvironmentConfig env;
  env.closeness = config.GetString("env.closeness") == "log" ? ClosenessTransform::kLog
                                                             : ClosenessTransform::kLinear;
  env.test_mode = config.GetBool("env.test_mode");
  env.max_steps = config.GetInt("env.max_steps");
  env.goal_radius = config.GetDouble("env.goal_radius");
  env.goal_progress = config.GetDouble("env.goal_progress");
  env.min_cumulative_reward = config.GetDouble("env.min_cumulative_reward");
  return env;
}

}  // namespace colav

#include "env/environment_config.h"

#include "src/error.h"

namespace colav {
namespace {

// Bounds of the scan history: a ring of at most 16 x 100 scans (1.1 MB) per world.
constexpr int kMaxScanHistory = 15;
constexpr int kMaxScanHistoryInterval = 100;
// An obstacle list kept longer than an episode's default 2,000 steps is a typo.
constexpr int kMaxObstacleListRefresh = 2000;

}  // namespace

ClosenessTransform ParseClosenessTransform(const std::string& name) {
  if (name == "linear") return ClosenessTransform::kLinear;
  if (name == "log") return ClosenessTransform::kLog;
  throw UserError("unknown closeness transform '" + name + "' (expected linear or log)");
}

std::string ClosenessTransformName(ClosenessTransform transform) {
  return transform == ClosenessTransform::kLog ? "log" : "linear";
}

TextCodec<ClosenessTransform> ClosenessTransformCodec() {
  return {ClosenessTransformName, ParseClosenessTransform};
}

OptionsBinding<EnvironmentConfig> EnvironmentBinding() {
  using Env = EnvironmentConfig;
  OptionsBinding<Env> binding;
  binding
      .Coded("env.closeness", &Env::closeness,
             "range -> closeness: linear 1-d/150 (paper) or log 1-ln(1+d)/ln151 (reference code)",
             ClosenessTransformCodec(), {"linear", "log"})
      .Bool("env.test_mode", &Env::test_mode,
            "switch off the cumulative-reward termination (reference test procedure)")
      .Number("env.max_steps", &Env::max_steps, "steps before an episode is truncated", 1, 1000000)
      .Number("env.goal_radius", &Env::goal_radius, "goal reached within this distance (m)", 0.0,
              1000.0)
      .Number("env.goal_progress", &Env::goal_progress,
              "goal reached when progress s*/L reaches this", 0.0, 2.0)
      .Number("env.min_cumulative_reward", &Env::min_cumulative_reward,
              "training episodes end below this cumulative reward")
      .Number("env.scan_history", &Env::scan_history,
              "earlier range scans appended to the observation (0: the paper's observation)", 0,
              kMaxScanHistory)
      .Number("env.scan_history_interval", &Env::scan_history_interval,
              "steps between two scans of that history", 1, kMaxScanHistoryInterval)
      .Number("env.obstacle_list_refresh", &Env::obstacle_list_refresh,
              "0: the range-finder sees every obstacle every step; N: only those within 150 m of "
              "the hull at the reset or the last multiple of N steps (the reference's list, 25 in "
              "the authors' training; collisions unaffected)",
              0, kMaxObstacleListRefresh);
  return binding;
}

}  // namespace colav

// The environment's configuration keys (section `env.` of every program's config), bound to the
// fields of EnvironmentConfig, and the names of the closeness transforms.
#pragma once

#include <string>

#include "env/environment_spec.h"
#include "src/options_binding.h"

namespace colav {

/// "linear" or "log"; anything else is a UserError naming the value.
ClosenessTransform ParseClosenessTransform(const std::string& name);
/// The inverse of ParseClosenessTransform.
std::string ClosenessTransformName(ClosenessTransform transform);
/// The two together, for an options binding.
TextCodec<ClosenessTransform> ClosenessTransformCodec();

/// env.closeness, env.test_mode, env.max_steps, env.goal_radius, env.goal_progress,
/// env.min_cumulative_reward, env.scan_history, env.scan_history_interval,
/// env.obstacle_list_refresh; a program includes them with its own defaults.
OptionsBinding<EnvironmentConfig> EnvironmentBinding();

}  // namespace colav

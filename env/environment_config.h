// The environment's configuration keys (section `env.` of every program's config).
#pragma once

#include "env/environment_spec.h"
#include "src/config.h"

namespace colav {

/// Declares env.closeness, env.test_mode, env.max_steps, env.goal_radius, env.goal_progress,
/// env.min_cumulative_reward with the paper's defaults.
void AddEnvironmentKeys(ConfigSchema& schema);

/// The EnvironmentConfig of a resolved configuration that declared AddEnvironmentKeys.
EnvironmentConfig EnvironmentConfigFrom(const Config& config);

}  // namespace colav

// The configuration keys of the training worlds (section `world.` of train_ppo's config), bound to
// the fields of TrainingScenarioConfig. They change only where an agent trains: the test scenarios
// are always the paper's (evaluation_episodes.cpp).
#pragma once

#include "env/training_scenario.h"
#include "src/options_binding.h"

namespace colav {

/// world.num_moving, world.moving_displacement_sd, world.num_static, world.static_displacement_sd,
/// with the paper's values as defaults.
OptionsBinding<TrainingScenarioConfig> TrainingScenarioBinding();

}  // namespace colav

// The configuration keys of a kind of training world (sections `world.` and `world2.` of
// train_ppo's config), bound to the fields of TrainingScenarioConfig. They change only where an
// agent trains: the test scenarios are always the paper's (evaluation_episodes.cpp).
#pragma once

#include <string>

#include "env/training_scenario.h"
#include "src/options_binding.h"

namespace colav {

/// PREFIX.num_moving, PREFIX.moving_displacement_sd, PREFIX.num_static,
/// PREFIX.static_displacement_sd, with the paper's values as defaults.
OptionsBinding<TrainingScenarioConfig> TrainingScenarioBinding(const std::string& prefix);

}  // namespace colav

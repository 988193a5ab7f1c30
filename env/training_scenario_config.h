// The configuration keys of a kind of training world (sections `world.` and `world2.` of
// train_ppo's config), bound to the fields of TrainingScenarioConfig. They change only where an
// agent trains: the test scenarios are always the paper's (evaluation_episodes.cpp).
#pragma once

#include <string>
#include <vector>

#include "env/training_scenario.h"
#include "src/options_binding.h"

namespace colav {

/// PREFIX.num_moving, PREFIX.moving_displacement_sd, PREFIX.num_static,
/// PREFIX.static_displacement_sd, PREFIX.path_bends, with the paper's values as defaults.
OptionsBinding<TrainingScenarioConfig> TrainingScenarioBinding(const std::string& prefix);

/// How many of a batch of `num_worlds` play a second kind of world given its share (train_ppo's
/// world2.share): the share rounded to whole worlds.
int SecondKindWorlds(double second_share, int num_worlds);

/// The kind of each of `num_worlds` worlds: `first`, then SecondKindWorlds(second_share,
/// num_worlds) of `second`, the last ones (train_ppo's world.* and world2.*, and the Python
/// module's `world` and `world2`).
std::vector<TrainingScenarioConfig> MixedWorlds(const TrainingScenarioConfig& first,
                                                const TrainingScenarioConfig& second,
                                                double second_share, int num_worlds);

}  // namespace colav

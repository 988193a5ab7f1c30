// Settings given as Python keywords (`max_steps=500`, `world={"num_static": 22}`), read and
// validated exactly as the programs read their env.* and world.* keys, so both accept the same
// values with the same errors.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "env/environment_spec.h"
#include "env/training_scenario.h"
#include "src/config.h"

namespace colav::python {

/// Options with the resolved value of every key of their section (for `settings`, `world`).
template <typename Options>
struct Resolved {
  Options config;
  std::vector<std::pair<std::string, ConfigValue>> values;  ///< keyword name -> value
};
/// The environment: the env.* keys.
using ResolvedSettings = Resolved<EnvironmentConfig>;
/// The training worlds: the world.* keys of train_ppo.
using ResolvedWorld = Resolved<TrainingScenarioConfig>;

/// The configuration of `texts` (keyword name -> value as text, e.g. "max_steps" -> "500") over
/// the defaults. An unknown name or a bad value is a UserError naming `origin` and the key.
ResolvedSettings ResolveSettings(const std::map<std::string, std::string>& texts,
                                 const std::string& origin);
/// The same for a kind of training world (e.g. "num_static" -> "22") over the paper's, read as
/// train_ppo reads its `section`.* keys (section "world" or "world2", which errors name).
ResolvedWorld ResolveWorld(const std::map<std::string, std::string>& texts,
                           const std::string& origin, const std::string& section);

/// Each setting: keyword name, default value and documentation, in the schema's order.
struct SettingDoc {
  std::string name;
  ConfigValue default_value;
  std::string doc;
};
std::vector<SettingDoc> SettingDocs();
/// The same for the world keys.
std::vector<SettingDoc> WorldSettingDocs();

}  // namespace colav::python

// Environment settings given as Python keywords (`max_steps=500`), read and validated exactly as
// the programs read their env.* keys, so both accept the same values with the same errors.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "env/environment_spec.h"
#include "src/config.h"

namespace colav::python {

/// An environment configuration with the resolved value of every setting (for `settings`).
struct ResolvedSettings {
  EnvironmentConfig config;
  std::vector<std::pair<std::string, ConfigValue>> values;  ///< keyword name -> value
};

/// The configuration of `texts` (keyword name -> value as text, e.g. "max_steps" -> "500") over
/// the defaults. An unknown name or a bad value is a UserError naming `origin` and the key.
ResolvedSettings ResolveSettings(const std::map<std::string, std::string>& texts,
                                 const std::string& origin);

/// Each setting: keyword name, default value and documentation, in the schema's order.
struct SettingDoc {
  std::string name;
  ConfigValue default_value;
  std::string doc;
};
std::vector<SettingDoc> SettingDocs();

}  // namespace colav::python

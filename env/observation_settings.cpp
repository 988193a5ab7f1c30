#include "env/observation_settings.h"

#include <yaml-cpp/yaml.h>

#include "env/environment_config.h"
#include "src/error.h"
#include "src/yaml_file.h"

namespace colav {
namespace {

constexpr char kClosenessKey[] = "closeness";

std::string ClosenessFormula(ClosenessTransform transform) {
  return transform == ClosenessTransform::kLog ? "1 - ln(1+d)/ln(151)" : "1 - d/150";
}

YAML::Node LoadYamlText(const std::string& text, const std::string& source) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw UserError(source + ": malformed observation settings (" + e.msg + ")");
  }
}

// The settings of a parsed record or sidecar; `source` names it in errors.
ObservationSettings SettingsFromYaml(const YAML::Node& root, const std::string& source) {
  if (!root.IsMap() || root.size() != 1 || !root["env"] || !root["env"].IsMap()) {
    throw UserError(source + ": observation settings must be one map 'env:' (e.g. env: {" +
                    kClosenessKey + ": log})");
  }
  ObservationSettings settings;
  for (const auto& item : root["env"]) {
    const std::string key = item.first.as<std::string>();
    if (key != kClosenessKey) {
      throw UserError(source + ": env." + key +
                      " is not an observation setting (only env.closeness belongs here)");
    }
    if (!item.second.IsScalar()) throw UserError(source + ": env.closeness must be a word");
    try {
      settings.closeness = ParseClosenessTransform(item.second.as<std::string>());
    } catch (const UserError& e) {
      throw UserError(source + ": env.closeness: " + e.what());
    }
  }
  return settings;
}

}  // namespace

ObservationSettings ObservationSettingsOf(const EnvironmentConfig& config) {
  return {config.closeness};
}

EnvironmentConfig WithObservationSettings(EnvironmentConfig config,
                                          const ObservationSettings& settings) {
  config.closeness = settings.closeness;
  return config;
}

std::string DescribeObservationSettings(const ObservationSettings& settings) {
  return std::string(kClosenessKey) + " " + ClosenessTransformName(settings.closeness);
}

std::string ObservationSettingsYaml(const ObservationSettings& settings) {
  return "env:\n  " + std::string(kClosenessKey) + ": " +
         ClosenessTransformName(settings.closeness) + "\n";
}

ObservationSettings ParseObservationSettingsYaml(const std::string& text,
                                                 const std::string& source) {
  return SettingsFromYaml(LoadYamlText(text, source), source);
}

ObservationSettings LoadObservationSettingsFile(const std::filesystem::path& path) {
  return SettingsFromYaml(LoadYamlFile(path), path.string());
}

std::string ObservationLayoutText(const ObservationSettings& settings) {
  return "obs[:, 0:6] = [u, v, r, cte/100, heading_error, look_ahead_heading_error]; "
         "obs[:, 6:186] = closeness " +
         ClosenessFormula(settings.closeness) +
         " of the range d (m) of rays i = 0..179 at -pi + (i+1)*2 deg";
}

}  // namespace colav

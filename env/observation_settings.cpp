#include "env/observation_settings.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <iterator>

#include "env/environment_config.h"
#include "src/config.h"
#include "src/error.h"
#include "src/yaml_file.h"

namespace colav {
namespace {

// The keys of the env section that are observation settings, in the order they are written.
constexpr char kClosenessKey[] = "closeness";
constexpr char kScanHistoryKey[] = "scan_history";
constexpr char kScanHistoryIntervalKey[] = "scan_history_interval";
const char* const kObservationKeys[] = {kClosenessKey, kScanHistoryKey, kScanHistoryIntervalKey};

std::string ClosenessFormula(ClosenessTransform transform) {
  return transform == ClosenessTransform::kLog ? "1 - ln(1+d)/ln(151)" : "1 - d/150";
}

bool IsObservationKey(const std::string& key) {
  return std::find(std::begin(kObservationKeys), std::end(kObservationKeys), key) !=
         std::end(kObservationKeys);
}

YAML::Node LoadYamlText(const std::string& text, const std::string& source) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw UserError(source + ": malformed observation settings (" + e.msg + ")");
  }
}

// The settings of a parsed record or sidecar, each value validated as the env.* key of a
// program's configuration; `source` names it in errors.
ObservationSettings SettingsFromYaml(const YAML::Node& root, const std::string& source) {
  if (!root.IsMap() || root.size() != 1 || !root["env"] || !root["env"].IsMap()) {
    throw UserError(source + ": observation settings must be one map 'env:' (e.g. env: {" +
                    kClosenessKey + ": log})");
  }
  const OptionsBinding<EnvironmentConfig> binding = EnvironmentBinding();
  Config config = Config::Defaults(binding.Schema());
  for (const auto& item : root["env"]) {
    const std::string key = item.first.as<std::string>();
    if (!IsObservationKey(key)) {
      throw UserError(fmt::format(
          "{}: env.{} is not an observation setting (only env.closeness, env.scan_history and "
          "env.scan_history_interval belong here)",
          source, key));
    }
    if (!item.second.IsScalar()) {
      throw UserError(fmt::format("{}: env.{} must be a value", source, key));
    }
    config.Set("env." + key, item.second.as<std::string>(), source);
  }
  return ObservationSettingsOf(binding.Read(config));
}

}  // namespace

ObservationSettings ObservationSettingsOf(const EnvironmentConfig& config) {
  return {config.closeness, config.scan_history, config.scan_history_interval};
}

EnvironmentConfig WithObservationSettings(EnvironmentConfig config,
                                          const ObservationSettings& settings) {
  config.closeness = settings.closeness;
  config.scan_history = settings.scan_history;
  config.scan_history_interval = settings.scan_history_interval;
  return config;
}

int ObservationSize(const ObservationSettings& settings) {
  return ObservationSize(WithObservationSettings(EnvironmentConfig{}, settings));
}

std::string DescribeObservationSettings(const ObservationSettings& settings) {
  std::string text = std::string(kClosenessKey) + " " + ClosenessTransformName(settings.closeness);
  if (settings.scan_history > 0) {
    text += ", scan history " + std::to_string(settings.scan_history) + " every " +
            std::to_string(settings.scan_history_interval) + " steps";
  }
  return text;
}

std::string ObservationSettingsYaml(const ObservationSettings& settings) {
  std::string yaml = "env:\n  " + std::string(kClosenessKey) + ": " +
                     ClosenessTransformName(settings.closeness) + "\n";
  if (settings.scan_history > 0) {  // files without a history stay as they were
    yaml += "  " + std::string(kScanHistoryKey) + ": " + std::to_string(settings.scan_history) +
            "\n  " + kScanHistoryIntervalKey + ": " +
            std::to_string(settings.scan_history_interval) + "\n";
  }
  return yaml;
}

ObservationSettings ParseObservationSettingsYaml(const std::string& text,
                                                 const std::string& source) {
  return SettingsFromYaml(LoadYamlText(text, source), source);
}

ObservationSettings LoadObservationSettingsFile(const std::filesystem::path& path) {
  return SettingsFromYaml(LoadYamlFile(path), path.string());
}

std::string ObservationLayoutText(const ObservationSettings& settings) {
  std::string text =
      "obs[:, 0:6] = [u, v, r, cte/100, heading_error, look_ahead_heading_error]; "
      "obs[:, 6:186] = closeness " +
      ClosenessFormula(settings.closeness) +
      " of the range d (m) of rays i = 0..179 at -pi + (i+1)*2 deg";
  if (settings.scan_history > 0) {
    const int end = kNavigationSize + kNumRays * (1 + settings.scan_history);
    text += fmt::format(
        "; obs[:, {}:{}] = the scans of {} earlier steps, {} steps apart (k = 1..{}: obs[:, "
        "6+180k:186+180k] is the scan of {}k steps before; the first scan of the episode while "
        "there is none)",
        kObservationSize, end, settings.scan_history, settings.scan_history_interval,
        settings.scan_history, settings.scan_history_interval);
  }
  return text;
}

}  // namespace colav

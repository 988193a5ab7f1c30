// The settings that decide what the numbers of an observation mean: the closeness transform and
// the scan history (how many earlier scans follow the current one, how many steps apart). A trained
// model is only valid under the settings it was trained with, so model files record them (spec
// interfaces.md, "Observation settings travel with models") in the format of a policy's sidecar
// YAML file:
//
//   env:
//     closeness: log
//     scan_history: 3             # only when there is a history
//     scan_history_interval: 5
#pragma once

#include <filesystem>
#include <string>

#include "env/environment_spec.h"

namespace colav {

struct ObservationSettings {
  ClosenessTransform closeness = ClosenessTransform::kLinear;
  int scan_history = 0;
  int scan_history_interval = 5;  ///< meaningless without a history

  bool operator==(const ObservationSettings& other) const {
    return closeness == other.closeness && scan_history == other.scan_history &&
           (scan_history == 0 || scan_history_interval == other.scan_history_interval);
  }
  bool operator!=(const ObservationSettings& other) const { return !(*this == other); }
};

/// The observation settings of an environment configuration.
ObservationSettings ObservationSettingsOf(const EnvironmentConfig& config);

/// `config` with its observation settings replaced by `settings` (the rest is the caller's).
EnvironmentConfig WithObservationSettings(EnvironmentConfig config,
                                          const ObservationSettings& settings);

/// Floats in an observation under `settings` (ObservationSize of environment_spec.h).
int ObservationSize(const ObservationSettings& settings);

/// "closeness log" (", scan history 3 every 5 steps"): for logs and tables.
std::string DescribeObservationSettings(const ObservationSettings& settings);

/// The YAML text above, as model files record it.
std::string ObservationSettingsYaml(const ObservationSettings& settings);

/// Parses that YAML text. A malformed text, a key other than those above or a bad value is a
/// UserError naming `source` (the file the text came from) and the key.
ObservationSettings ParseObservationSettingsYaml(const std::string& text,
                                                 const std::string& source);

/// The same for a sidecar file.
ObservationSettings LoadObservationSettingsFile(const std::filesystem::path& path);

/// One line describing the observation layout under `settings`, closeness formula included.
std::string ObservationLayoutText(const ObservationSettings& settings);

}  // namespace colav

// Whether a finished run still answers the study: the settings its program recorded
// (RUN/config.yaml) against those the study now asks for (the program's --print-config). A study
// reuses finished runs, so without this a study file whose steps, seeds or keys changed would
// report the old runs as the new ones.
#pragma once

#include <optional>
#include <string>

namespace colav {

/// The first setting, in `printed`'s order, that both YAML configurations hold with different
/// values, as "KEY = RECORDED, the study asks for PRINTED"; nullopt when none. Paths (values with
/// a '/': runs copied between study folders name other files) and thread counts (the study sets
/// them from --jobs; they change no result) are not compared. A key one side lacks is not
/// compared: runs made before a key existed ran with its default. A record that is not YAML
/// holds no setting to compare.
std::optional<std::string> FirstSettingDifference(const std::string& recorded,
                                                  const std::string& printed);

}  // namespace colav

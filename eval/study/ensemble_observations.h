// Before any job runs: the runs an ensemble combines must share their observation settings, or
// ensemble_policy refuses them, but only once they are trained. The settings of a configuration's
// runs (env.closeness, env.scan_history and, with a history, env.scan_history_interval) are read
// from the configuration train_ppo resolved for its first run: its --print-config output, or the
// config.yaml of a run already trained.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "eval/study/study_spec.h"

namespace colav {

/// A UserError naming the study file, the ensemble kind and the two configurations whose runs
/// observe differently. `printed`: resolved configurations by job id (CheckJobConfigurations);
/// a configuration in neither `printed` nor a trained run is not checked.
void CheckEnsembleObservationSettings(const StudySpec& spec,
                                      const std::filesystem::path& study_file,
                                      const std::filesystem::path& out,
                                      const std::map<std::string, std::string>& printed);

}  // namespace colav

#include "eval/study/ensemble_observations.h"

#include <yaml-cpp/yaml.h>

#include <optional>

#include "eval/study/job_graph.h"
#include "src/error.h"

namespace colav {
namespace {

// "env.closeness log, env.scan_history 0" of a resolved train_ppo configuration.
std::string ObservationKeys(const YAML::Node& config) {
  const YAML::Node env = config["env"];
  const std::string history = env["scan_history"].as<std::string>();
  std::string keys =
      "env.closeness " + env["closeness"].as<std::string>() + ", env.scan_history " + history;
  if (history != "0") {
    keys += ", env.scan_history_interval " + env["scan_history_interval"].as<std::string>();
  }
  return keys;
}

// The observation keys of `config`'s runs, if its first run's configuration is known.
std::optional<std::string> RunObservationKeys(const std::string& config,
                                              const std::filesystem::path& out,
                                              const std::map<std::string, std::string>& printed) {
  const std::filesystem::path first_run = RunFolder(config, 0);
  const auto resolved = printed.find(first_run.string());
  const std::filesystem::path trained = out / first_run / "config.yaml";
  if (resolved == printed.end() && !std::filesystem::exists(trained)) return std::nullopt;
  try {
    return ObservationKeys(resolved != printed.end() ? YAML::Load(resolved->second)
                                                     : YAML::LoadFile(trained.string()));
  } catch (const YAML::Exception&) {
    return std::nullopt;  // unreadable, or not train_ppo's configuration: nothing to compare
  }
}

}  // namespace

void CheckEnsembleObservationSettings(const StudySpec& spec,
                                      const std::filesystem::path& study_file,
                                      const std::filesystem::path& out,
                                      const std::map<std::string, std::string>& printed) {
  for (const EnsembleSpec& ensemble : spec.ensembles) {
    std::optional<std::pair<std::string, std::string>> first;  // configuration, its keys
    for (const std::string& member : ensemble.members) {
      const std::optional<std::string> keys = RunObservationKeys(member, out, printed);
      if (!keys) continue;
      if (!first) {
        first.emplace(member, *keys);
      } else if (*keys != first->second) {
        throw UserError(study_file.string() + ": ensembles." + ensemble.name + ": the runs of " +
                        first->first + " (" + first->second + ") and of " + member + " (" + *keys +
                        ") observe differently; ensemble_policy would refuse them");
      }
    }
  }
}

}  // namespace colav

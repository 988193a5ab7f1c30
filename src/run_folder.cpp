#include "src/run_folder.h"

#include <algorithm>
#include <map>
#include <system_error>
#include <utility>

#include "src/atomic_file.h"
#include "src/cli.h"
#include "src/error.h"

namespace colav {
namespace {

// Flattens a nested JSON object into dotted keys ("ppo.n_envs") and their values' text.
void Flatten(const nlohmann::json& json, const std::string& prefix,
             std::map<std::string, std::string>& flat) {
  for (const auto& [key, value] : json.items()) {
    if (value.is_object()) {
      Flatten(value, prefix + key + ".", flat);
    } else {
      flat[prefix + key] = value.is_string() ? value.get<std::string>() : value.dump();
    }
  }
}

std::map<std::string, std::string> FlatValues(const Config& config) {
  std::map<std::string, std::string> flat;
  Flatten(config.ToJson(), "", flat);
  return flat;
}

}  // namespace

std::optional<DifferingSetting> FirstDifferingSetting(const Config& config, const Config& recorded,
                                                      const std::vector<std::string>& free_keys) {
  const std::map<std::string, std::string> stored = FlatValues(recorded);
  const std::map<std::string, std::string> current = FlatValues(config);
  const auto changed = std::find_if(current.begin(), current.end(), [&](const auto& entry) {
    const bool free = std::find(free_keys.begin(), free_keys.end(), entry.first) != free_keys.end();
    const auto original = stored.find(entry.first);
    return !free && (original == stored.end() || original->second != entry.second);
  });
  if (changed == current.end()) return std::nullopt;
  const auto original = stored.find(changed->first);
  return DifferingSetting{changed->first, changed->second,
                          original == stored.end() ? "(none)" : original->second};
}

RunFolder::RunFolder(std::filesystem::path path, std::string program)
    : path_(std::move(path)),
      program_(std::move(program)),
      lock_(std::make_shared<const RunLock>(path_, program_)) {}

RunFolder RunFolder::Create(const std::filesystem::path& dir, const std::string& program) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) {
    const std::string reason = error ? error.message() : "not a folder";
    throw UserError(dir.string() + ": cannot create run folder (" + reason + ")");
  }
  return RunFolder(dir, program.empty() ? ProgramName() : program);
}

std::filesystem::path RunFolder::DefaultPath(const std::string& name) {
  return std::filesystem::path("runs") / name;
}

void RunFolder::StartNewRun(const std::vector<std::string>& markers,
                            const std::vector<std::string>& outputs, bool overwrite,
                            const std::string& hint) const {
  const auto marker = std::find_if(markers.begin(), markers.end(), [&](const std::string& name) {
    return std::filesystem::exists(path_ / name);
  });
  if (!overwrite && marker != markers.end()) {
    throw UserError(path_.string() + " holds a run (" + *marker + "): " + hint);
  }
  for (const std::string& output : outputs) std::filesystem::remove_all(path_ / output);
}

void RunFolder::RequireConfigUnchanged(const Config& config, const ConfigSchema& schema,
                                       const std::vector<std::string>& free_keys) const {
  const std::filesystem::path stored_path = path_ / "config.yaml";
  if (!std::filesystem::is_regular_file(stored_path)) {
    throw UserError(path_.string() + ": no config.yaml to continue the run with");
  }
  RequireConfigUnchanged(config, Config::Load(schema, stored_path.string()), stored_path.string(),
                         free_keys);
}

void RunFolder::RequireConfigUnchanged(const Config& config, const Config& recorded,
                                       const std::string& source,
                                       const std::vector<std::string>& free_keys) const {
  const std::optional<DifferingSetting> changed =
      FirstDifferingSetting(config, recorded, free_keys);
  if (!changed) return;
  throw UserError(path_.string() + ": '" + changed->key + "' = " + changed->value +
                  " differs from the run's " + changed->recorded_value + " (" + source +
                  "); a run continues with its configuration");
}

void RunFolder::WriteResolvedConfig(const Config& config) const {
  WriteTextFileAtomically(path_ / "config.yaml", config.ToYaml());
}

std::filesystem::path RunFolder::LogPath() const { return path_ / (program_ + ".log"); }

}  // namespace colav

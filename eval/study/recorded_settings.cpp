#include "eval/study/recorded_settings.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <map>
#include <utility>
#include <vector>

namespace colav {
namespace {

// Every scalar of a configuration as ("section.key", value), in the file's order; none when the
// text is not YAML.
std::vector<std::pair<std::string, std::string>> Settings(const std::string& yaml) {
  std::vector<std::pair<std::string, std::string>> settings;
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception&) {
    return settings;
  }
  if (!root.IsMap()) return settings;
  for (const auto& section : root) {
    if (!section.second.IsMap()) continue;
    for (const auto& key : section.second) {
      if (!key.second.IsScalar()) continue;
      settings.emplace_back(section.first.as<std::string>() + "." + key.first.as<std::string>(),
                            key.second.as<std::string>());
    }
  }
  return settings;
}

bool Compared(const std::string& key, const std::string& value) {
  const std::string threads = "threads";
  const bool thread_count = key.size() >= threads.size() &&
                            key.compare(key.size() - threads.size(), threads.size(), threads) == 0;
  return !thread_count && value.find('/') == std::string::npos;
}

}  // namespace

std::optional<std::string> FirstSettingDifference(const std::string& recorded,
                                                  const std::string& printed) {
  std::map<std::string, std::string> recorded_settings;
  for (auto& [key, value] : Settings(recorded)) recorded_settings[key] = value;
  for (const auto& [key, value] : Settings(printed)) {
    const auto old = recorded_settings.find(key);
    if (old == recorded_settings.end() || old->second == value || !Compared(key, value)) continue;
    return fmt::format("{} = {}, the study asks for {}", key, old->second, value);
  }
  return std::nullopt;
}

}  // namespace colav

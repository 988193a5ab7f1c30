#include "python/settings.h"

#include "env/environment_config.h"

namespace colav::python {
namespace {

// Keywords are the env.* keys without their section: `closeness` is env.closeness.
constexpr char kSection[] = "env.";

std::string KeywordOf(const std::string& key) { return key.substr(sizeof kSection - 1); }

}  // namespace

ResolvedSettings ResolveSettings(const std::map<std::string, std::string>& texts,
                                 const std::string& origin) {
  const OptionsBinding<EnvironmentConfig> binding = EnvironmentBinding();
  const ConfigSchema schema = binding.Schema();
  Config config = Config::Defaults(schema);
  for (const auto& [name, text] : texts) config.Set(kSection + name, text, origin);
  ResolvedSettings resolved{binding.Read(config), {}};
  for (const ConfigSchema::Entry& entry : schema.entries()) {
    resolved.values.emplace_back(KeywordOf(entry.key), config.Value(entry.key));
  }
  return resolved;
}

std::vector<SettingDoc> SettingDocs() {
  const ConfigSchema schema = EnvironmentBinding().Schema();
  std::vector<SettingDoc> docs;
  for (const ConfigSchema::Entry& entry : schema.entries()) {
    docs.push_back({KeywordOf(entry.key), entry.default_value, entry.doc});
  }
  return docs;
}

}  // namespace colav::python

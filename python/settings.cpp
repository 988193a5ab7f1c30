#include "python/settings.h"

#include "env/environment_config.h"
#include "env/training_scenario_config.h"

namespace colav::python {
namespace {

// The sections whose keys are keywords: `closeness` is env.closeness, `num_static` (in `world`)
// is world.num_static.
constexpr char kEnvSection[] = "env";
constexpr char kWorldSection[] = "world";

std::string KeyOf(const std::string& section, const std::string& keyword) {
  return section + "." + keyword;
}

std::string KeywordOf(const std::string& key) { return key.substr(key.find('.') + 1); }

template <typename Options>
Resolved<Options> Resolve(const OptionsBinding<Options>& binding, const std::string& section,
                          const std::map<std::string, std::string>& texts,
                          const std::string& origin) {
  const ConfigSchema schema = binding.Schema();
  Config config = Config::Defaults(schema);
  for (const auto& [name, text] : texts) config.Set(KeyOf(section, name), text, origin);
  Resolved<Options> resolved{binding.Read(config), {}};
  for (const ConfigSchema::Entry& entry : schema.entries()) {
    resolved.values.emplace_back(KeywordOf(entry.key), config.Value(entry.key));
  }
  return resolved;
}

std::vector<SettingDoc> DocsOf(const ConfigSchema& schema) {
  std::vector<SettingDoc> docs;
  for (const ConfigSchema::Entry& entry : schema.entries()) {
    docs.push_back({KeywordOf(entry.key), entry.default_value, entry.doc});
  }
  return docs;
}

}  // namespace

ResolvedSettings ResolveSettings(const std::map<std::string, std::string>& texts,
                                 const std::string& origin) {
  return Resolve(EnvironmentBinding(), kEnvSection, texts, origin);
}

ResolvedWorld ResolveWorld(const std::map<std::string, std::string>& texts,
                           const std::string& origin, const std::string& section) {
  return Resolve(TrainingScenarioBinding(section), section, texts, origin);
}

std::vector<SettingDoc> SettingDocs() { return DocsOf(EnvironmentBinding().Schema()); }

std::vector<SettingDoc> WorldSettingDocs() {
  return DocsOf(TrainingScenarioBinding(kWorldSection).Schema());
}

}  // namespace colav::python

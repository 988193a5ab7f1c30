// Configuration with a schema: every key a program understands is declared with its type,
// default, range and documentation, so a typo or a bad value in a YAML file or a --set override is
// reported as a one-line colav::UserError before any work starts.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

namespace YAML {
class Node;
}  // namespace YAML

namespace colav {

/// A configuration value: the alternative held is the key's type.
using ConfigValue = std::variant<double, std::int64_t, bool, std::string>;

/// Declares the known keys (dotted names like "ppo.learning_rate"), their type, default, doc and
/// range. Declaring a bad key or default is a programming error (std::invalid_argument).
class ConfigSchema {
 public:
  struct Entry {
    std::string key;
    ConfigValue default_value;  // its alternative is the key's type
    std::string doc;
    double min_double = -std::numeric_limits<double>::infinity();
    double max_double = std::numeric_limits<double>::infinity();
    std::int64_t min_int = std::numeric_limits<std::int64_t>::min();
    std::int64_t max_int = std::numeric_limits<std::int64_t>::max();
    std::vector<std::string> choices;  // empty = any string
  };

  ConfigSchema& AddDouble(const std::string& key, double default_value, const std::string& doc,
                          double min = -std::numeric_limits<double>::infinity(),
                          double max = std::numeric_limits<double>::infinity());
  ConfigSchema& AddInt(const std::string& key, std::int64_t default_value, const std::string& doc,
                       std::int64_t min = std::numeric_limits<std::int64_t>::min(),
                       std::int64_t max = std::numeric_limits<std::int64_t>::max());
  ConfigSchema& AddBool(const std::string& key, bool default_value, const std::string& doc);
  ConfigSchema& AddString(const std::string& key, const std::string& default_value,
                          const std::string& doc, std::vector<std::string> choices = {});
  /// Declares a whole entry (its default's alternative is the key's type).
  ConfigSchema& Add(Entry entry);

  /// The entry of `key`, or nullptr when the key is not declared.
  const Entry* Find(const std::string& key) const;
  /// The entries in declaration order.
  const std::vector<Entry>& entries() const { return entries_; }
  /// One line per key (name, type, default, range or choices, doc), for --help.
  std::string Describe() const;

 private:
  std::vector<Entry> entries_;
  std::map<std::string, std::size_t> index_;  // key -> position in entries_
};

/// Resolved configuration values: schema defaults, then a YAML file, then overrides.
class Config {
 public:
  /// Defaults, then the YAML file (nested maps; keys flattened with '.'), then overrides
  /// "key=value" in order. yaml_path "" = no file.
  static Config Load(const ConfigSchema& schema, const std::string& yaml_path,
                     const std::vector<std::string>& overrides = {});
  static Config Defaults(const ConfigSchema& schema);
  /// Defaults, then the nested YAML `text` (ToYaml's form) recorded in `origin`, which errors
  /// name (a checkpoint that keeps the configuration its run was trained with).
  static Config FromYamlText(const ConfigSchema& schema, const std::string& text,
                             const std::string& origin);

  /// Sets `key` from its text form, validated like an override; errors name `origin` (e.g.
  /// "--steps").
  void Set(const std::string& key, const std::string& value, const std::string& origin);
  /// Applies one "key=value" override; errors name `origin` (e.g. "--set").
  void ApplyOverride(const std::string& assignment, const std::string& origin);

  // The getters throw std::invalid_argument for an undeclared key or a key of another type.
  double GetDouble(const std::string& key) const;
  std::int64_t GetInt(const std::string& key) const;
  bool GetBool(const std::string& key) const;
  std::string GetString(const std::string& key) const;
  /// The value of `key`, of its declared type.
  const ConfigValue& Value(const std::string& key) const;

  /// Nested YAML of all resolved values, in schema order (for the run folder).
  std::string ToYaml() const;
  /// ToYaml with each key's doc as a comment after its value; "" without keys (--print-config,
  /// configs/*.yaml).
  std::string ToDocumentedYaml() const;
  /// Nested JSON object of all resolved values.
  nlohmann::json ToJson() const;

 private:
  explicit Config(const ConfigSchema& schema);
  /// Merges the values of `root` (nested maps), read from `origin`.
  void MergeYaml(const YAML::Node& root, const std::string& origin);
  const ConfigValue& Get(const std::string& key, std::size_t type_index) const;

  ConfigSchema schema_;
  std::map<std::string, ConfigValue> values_;
};

}  // namespace colav

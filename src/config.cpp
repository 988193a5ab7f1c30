#include "src/config.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "src/error.h"
#include "src/number_text.h"
#include "src/yaml_file.h"

namespace colav {
namespace {

using Entry = ConfigSchema::Entry;

enum TypeIndex : std::size_t { kDouble = 0, kInt = 1, kBool = 2, kString = 3 };

const char* TypeName(std::size_t type_index) {
  static constexpr const char* kNames[] = {"double", "int", "bool", "string"};
  return kNames[type_index];
}

// What a value of the type looks like, for "expects ..." messages.
const char* Expectation(std::size_t type_index) {
  static constexpr const char* kExpectations[] = {"a number", "an integer", "true or false",
                                                  "a string"};
  return kExpectations[type_index];
}

// Shortest text that reads back as the same double, always with a '.' so that YAML 1.1 readers
// (PyYAML) also see a float: 3 -> "3.0", 1e-05 -> "1.0e-05".
std::string FormatDouble(double value) {
  std::string text = fmt::format("{}", value);
  if (!std::isfinite(value) || text.find('.') != std::string::npos) return text;
  const std::size_t exponent = text.find('e');
  return exponent == std::string::npos ? text + ".0" : text.insert(exponent, ".0");
}

// The value as an error message or the help shows it: strings quoted.
std::string FormatValue(const ConfigValue& value) {
  switch (value.index()) {
    case kDouble:
      return FormatDouble(std::get<double>(value));
    case kInt:
      return std::to_string(std::get<std::int64_t>(value));
    case kBool:
      return std::get<bool>(value) ? "true" : "false";
    default:
      return "'" + std::get<std::string>(value) + "'";
  }
}

// The declared range of a number key ("" when unbounded) or its choices.
std::string AllowedText(const Entry& entry) {
  std::string range;
  switch (entry.default_value.index()) {
    case kDouble:
      range = RangeText(entry.min_double, entry.max_double);
      break;
    case kInt:
      range = RangeText(entry.min_int, entry.max_int);
      break;
    default:
      return fmt::format("{}", fmt::join(entry.choices, ", "));
  }
  return range == "(-inf, inf)" ? "" : range;
}

bool IsAllowed(const Entry& entry, const ConfigValue& value) {
  switch (value.index()) {
    case kDouble:
      return std::get<double>(value) >= entry.min_double &&
             std::get<double>(value) <= entry.max_double;
    case kInt:
      return std::get<std::int64_t>(value) >= entry.min_int &&
             std::get<std::int64_t>(value) <= entry.max_int;
    case kString:
      return entry.choices.empty() || std::count(entry.choices.begin(), entry.choices.end(),
                                                 std::get<std::string>(value)) > 0;
    default:
      return true;
  }
}

// Why `value` is not allowed for `entry` ("= 0 is out of range [1, 1000]"), or "" when it is.
std::string ValueProblem(const Entry& entry, const ConfigValue& value) {
  if (IsAllowed(entry, value)) return "";
  const char* verdict = value.index() == kString ? " is not one of: " : " is out of range ";
  return "= " + FormatValue(value) + verdict + AllowedText(entry);
}

std::string Trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// The value `text` spells for a key of type `type_index`, or nullopt.
std::optional<ConfigValue> ParseText(std::size_t type_index, const std::string& text) {
  switch (type_index) {
    case kDouble:
      if (const auto real = ParseFiniteNumber(text)) return *real;
      return std::nullopt;
    case kInt:
      if (const auto integer = ParseWholeNumber(text)) return *integer;
      return std::nullopt;
    case kBool:
      if (text == "true" || text == "false") return text == "true";
      return std::nullopt;
    default:
      return text;
  }
}

// The value `text` denotes for `entry`; a UserError naming `origin` and the key otherwise.
ConfigValue ParseValue(const Entry& entry, const std::string& text, const std::string& origin) {
  const std::string prefix = origin + ": key '" + entry.key + "' ";
  const std::size_t type = entry.default_value.index();
  const std::optional<ConfigValue> value = ParseText(type, text);
  if (!value) throw UserError(prefix + "expects " + Expectation(type) + ", got '" + text + "'");
  const std::string problem = ValueProblem(entry, *value);
  if (!problem.empty()) throw UserError(prefix + problem);
  return *value;
}

std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

// "unknown key 'x'" plus the closest declared key when one is near (a typo or a missing prefix).
std::string UnknownKeyMessage(const ConfigSchema& schema, const std::string& key) {
  constexpr std::size_t kMaxTypoDistance = 3;
  std::string message = "unknown key '" + key + "'";
  std::size_t best_distance = kMaxTypoDistance + 1;
  const Entry* best = nullptr;
  for (const Entry& entry : schema.entries()) {
    const bool missing_prefix =
        entry.key.size() > key.size() &&
        entry.key.compare(entry.key.size() - key.size() - 1, std::string::npos, "." + key) == 0;
    const std::size_t distance = missing_prefix ? 0 : EditDistance(key, entry.key);
    if (distance < best_distance) {
      best_distance = distance;
      best = &entry;
    }
  }
  if (best != nullptr) message += " (did you mean '" + best->key + "'?)";
  return message;
}

bool IsValidKey(const std::string& key) {
  if (key.empty() || key.front() == '.' || key.back() == '.' ||
      key.find("..") != std::string::npos) {
    return false;
  }
  return std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
  });
}

// The keys nest as YAML/JSON maps, so one key cannot also be a map of others.
bool IsNestingConflict(const std::string& a, const std::string& b) {
  const auto is_prefix = [](const std::string& outer, const std::string& inner) {
    return inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 &&
           inner[outer.size()] == '.';
  };
  return is_prefix(a, b) || is_prefix(b, a);
}

// A YAML node as the text a value is parsed from; maps, lists and empty values are not values.
std::string ScalarText(const YAML::Node& node, const std::string& origin, const Entry& entry) {
  if (node.IsScalar()) return node.Scalar();
  const char* kind = node.IsMap() ? "a map" : node.IsSequence() ? "a list" : "an empty value";
  throw UserError(origin + ": key '" + entry.key + "' expects " +
                  Expectation(entry.default_value.index()) + ", got " + kind);
}

template <typename Json>
Json NestedValues(const ConfigSchema& schema, const std::map<std::string, ConfigValue>& values) {
  Json nested = Json::object();
  for (const Entry& entry : schema.entries()) {
    std::string pointer = "/" + entry.key;
    std::replace(pointer.begin(), pointer.end(), '.', '/');
    std::visit([&](const auto& value) { nested[typename Json::json_pointer(pointer)] = value; },
               values.at(entry.key));
  }
  return nested;
}

// Emits `node`, the nested values under the dotted `prefix`; with a schema, each value is followed
// by its key's doc as a comment.
void EmitYaml(YAML::Emitter& out, const nlohmann::ordered_json& node,
              const ConfigSchema* documenting = nullptr, const std::string& prefix = "") {
  if (node.is_object()) {
    out << YAML::BeginMap;
    for (const auto& item : node.items()) {
      out << YAML::Key << item.key() << YAML::Value;
      EmitYaml(out, item.value(), documenting, prefix + item.key() + ".");
    }
    out << YAML::EndMap;
    return;
  }
  if (node.is_string()) {
    out << YAML::DoubleQuoted << node.get<std::string>();  // "true" or "3" stay strings
  } else if (node.is_number_float()) {
    out << FormatDouble(node.get<double>());
  } else {
    out << node.dump();  // integers and booleans are spelled the same in JSON and YAML
  }
  if (documenting != nullptr) {
    out << YAML::Comment(documenting->Find(prefix.substr(0, prefix.size() - 1))->doc);
  }
}

Entry NewEntry(const std::string& key, ConfigValue default_value, const std::string& doc) {
  Entry entry;
  entry.key = key;
  entry.default_value = std::move(default_value);
  entry.doc = doc;
  return entry;
}

}  // namespace

ConfigSchema& ConfigSchema::AddDouble(const std::string& key, double default_value,
                                      const std::string& doc, double min, double max) {
  Entry entry = NewEntry(key, default_value, doc);
  entry.min_double = min;
  entry.max_double = max;
  return Add(std::move(entry));
}

ConfigSchema& ConfigSchema::AddInt(const std::string& key, std::int64_t default_value,
                                   const std::string& doc, std::int64_t min, std::int64_t max) {
  Entry entry = NewEntry(key, default_value, doc);
  entry.min_int = min;
  entry.max_int = max;
  return Add(std::move(entry));
}

ConfigSchema& ConfigSchema::AddBool(const std::string& key, bool default_value,
                                    const std::string& doc) {
  return Add(NewEntry(key, default_value, doc));
}

ConfigSchema& ConfigSchema::AddString(const std::string& key, const std::string& default_value,
                                      const std::string& doc, std::vector<std::string> choices) {
  Entry entry = NewEntry(key, default_value, doc);
  entry.choices = std::move(choices);
  return Add(std::move(entry));
}

ConfigSchema& ConfigSchema::Add(Entry entry) {
  const std::string where = "ConfigSchema: key '" + entry.key + "' ";
  if (!IsValidKey(entry.key)) throw std::invalid_argument(where + "is not a dotted name");
  if (index_.count(entry.key) > 0) throw std::invalid_argument(where + "is declared twice");
  for (const Entry& other : entries_) {
    if (IsNestingConflict(entry.key, other.key)) {
      throw std::invalid_argument(where + "conflicts with '" + other.key + "'");
    }
  }
  const std::string problem = ValueProblem(entry, entry.default_value);
  if (!problem.empty()) throw std::invalid_argument(where + "default " + problem);
  index_[entry.key] = entries_.size();
  entries_.push_back(std::move(entry));
  return *this;
}

const ConfigSchema::Entry* ConfigSchema::Find(const std::string& key) const {
  const auto found = index_.find(key);
  return found == index_.end() ? nullptr : &entries_[found->second];
}

std::string ConfigSchema::Describe() const {
  std::string text;
  for (const Entry& entry : entries_) {
    std::string kind = TypeName(entry.default_value.index());
    const std::string allowed = AllowedText(entry);
    if (!allowed.empty()) kind += (entry.choices.empty() ? " in " : ": ") + allowed;
    text += fmt::format("  {} = {} ({}) {}\n", entry.key, FormatValue(entry.default_value), kind,
                        entry.doc);
  }
  return text;
}

Config::Config(const ConfigSchema& schema) : schema_(schema) {
  for (const Entry& entry : schema_.entries()) values_[entry.key] = entry.default_value;
}

Config Config::Defaults(const ConfigSchema& schema) { return Config(schema); }

Config Config::Load(const ConfigSchema& schema, const std::string& yaml_path,
                    const std::vector<std::string>& overrides) {
  Config config(schema);
  if (!yaml_path.empty()) config.MergeYaml(LoadYamlFile(yaml_path), yaml_path);
  for (const std::string& assignment : overrides) config.ApplyOverride(assignment, "--set");
  return config;
}

Config Config::FromYamlText(const ConfigSchema& schema, const std::string& text,
                            const std::string& origin) {
  Config config(schema);
  config.MergeYaml(ParseYamlText(text, origin), origin);
  return config;
}

void Config::MergeYaml(const YAML::Node& root, const std::string& origin) {
  if (root.IsNull()) return;  // an empty file changes nothing
  if (!root.IsMap()) throw UserError(origin + ": expected a map of keys at the top level");
  // Depth-first over nested maps; a map under a name that is not a key is a group of keys.
  std::vector<std::pair<std::string, YAML::Node>> pending = {{"", root}};
  while (!pending.empty()) {
    auto [prefix, node] = pending.back();
    pending.pop_back();
    for (const auto& item : node) {
      const std::string key = prefix + item.first.Scalar();
      const Entry* entry = schema_.Find(key);
      if (entry != nullptr) {
        values_[key] = ParseValue(*entry, ScalarText(item.second, origin, *entry), origin);
      } else if (item.second.IsMap()) {
        pending.emplace_back(key + ".", item.second);
      } else {
        throw UserError(origin + ": " + UnknownKeyMessage(schema_, key));
      }
    }
  }
}

void Config::Set(const std::string& key, const std::string& value, const std::string& origin) {
  const Entry* entry = schema_.Find(key);
  if (entry == nullptr) throw UserError(origin + ": " + UnknownKeyMessage(schema_, key));
  values_[key] = ParseValue(*entry, value, origin);
}

void Config::ApplyOverride(const std::string& assignment, const std::string& origin) {
  const std::size_t equals = assignment.find('=');
  if (equals == std::string::npos) {
    throw UserError(origin + ": expected key=value, got '" + assignment + "'");
  }
  Set(Trim(assignment.substr(0, equals)), Trim(assignment.substr(equals + 1)), origin);
}

const ConfigValue& Config::Get(const std::string& key, std::size_t type_index) const {
  const ConfigValue& value = Value(key);
  if (value.index() != type_index) {
    throw std::invalid_argument("Config: key '" + key + "' is a " + TypeName(value.index()) +
                                ", not a " + TypeName(type_index));
  }
  return value;
}

const ConfigValue& Config::Value(const std::string& key) const {
  const Entry* entry = schema_.Find(key);
  if (entry == nullptr) throw std::invalid_argument("Config: undeclared key '" + key + "'");
  return values_.at(key);
}

double Config::GetDouble(const std::string& key) const {
  return std::get<double>(Get(key, kDouble));
}

std::int64_t Config::GetInt(const std::string& key) const {
  return std::get<std::int64_t>(Get(key, kInt));
}

bool Config::GetBool(const std::string& key) const { return std::get<bool>(Get(key, kBool)); }

std::string Config::GetString(const std::string& key) const {
  return std::get<std::string>(Get(key, kString));
}

std::string Config::ToYaml() const {
  YAML::Emitter out;
  EmitYaml(out, NestedValues<nlohmann::ordered_json>(schema_, values_));
  return std::string(out.c_str()) + "\n";
}

std::string Config::ToDocumentedYaml() const {
  if (schema_.entries().empty()) return "";
  YAML::Emitter out;
  EmitYaml(out, NestedValues<nlohmann::ordered_json>(schema_, values_), &schema_);
  return std::string(out.c_str()) + "\n";
}

nlohmann::json Config::ToJson() const { return NestedValues<nlohmann::json>(schema_, values_); }

}  // namespace colav

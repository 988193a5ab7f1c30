// One declaration per configuration key, bound to the field of a typed options struct that it sets:
// the struct's default value is the key's default, so a default lives in one place only. The
// binding yields the ConfigSchema (hence --help, validation, --print-config and configs/*.yaml)
// and reads a resolved Config into the struct.
//
//   OptionsBinding<PpoOptions> binding;
//   binding.Number("ppo.gamma", &PpoOptions::gamma, "discount factor", 0.0, 1.0)
//       .Number("ppo.clip_range", [](PpoOptions& o) -> auto& { return o.loss.clip_range; },
//               "PPO clip range", 0.0);
//   ConfigFlags config_flags(app, binding.Schema());  // --help, --config, --set, --print-config
//   ParseCommandLine(app, argc, argv);
//   const PpoOptions options = binding.Read(config_flags.Resolve());
//
// A field is named by a member pointer or by a lambda returning a reference to it (nested
// fields). Fields that are not a number, bool or string (enums, lists) are bound with Coded, by a
// pair of functions between the value and its text. Binding a key twice, or a default outside its
// range, is a programming error (std::invalid_argument, from ConfigSchema).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "src/config.h"

namespace colav {

/// How a value of type Value is written as text and read back (a bad text: a UserError).
template <typename Value>
struct TextCodec {
  std::function<std::string(const Value&)> format;
  std::function<Value(const std::string&)> parse;
};

template <typename Options>
class OptionsBinding {
  template <typename Access>
  using FieldOf = std::remove_reference_t<std::invoke_result_t<Access, Options&>>;
  // Range bounds of a number field as the schema stores them.
  template <typename Field>
  using BoundOf = std::conditional_t<std::is_floating_point_v<Field>, double, std::int64_t>;
  template <typename Field>
  static constexpr BoundOf<Field> Lowest() {
    if constexpr (std::is_floating_point_v<Field>) return -std::numeric_limits<double>::infinity();
    return std::numeric_limits<std::int64_t>::min();
  }
  template <typename Field>
  static constexpr BoundOf<Field> Highest() {
    if constexpr (std::is_floating_point_v<Field>) return std::numeric_limits<double>::infinity();
    return std::numeric_limits<std::int64_t>::max();
  }

 public:
  /// The keys' defaults are the fields of `defaults` (e.g. a program's own defaults).
  explicit OptionsBinding(Options defaults = Options()) : defaults_(std::move(defaults)) {}

  /// A double or integer field; min and max bound the accepted values.
  template <typename Access, typename Field = FieldOf<Access>>
  OptionsBinding& Number(const std::string& key, Access access, const std::string& doc,
                         BoundOf<Field> min = Lowest<Field>(),
                         BoundOf<Field> max = Highest<Field>()) {
    static_assert(std::is_arithmetic_v<Field> && !std::is_same_v<Field, bool>);
    ConfigSchema::Entry entry = NewEntry(key, doc);
    if constexpr (std::is_floating_point_v<Field>) {
      entry.min_double = min;
      entry.max_double = max;
    } else {
      entry.min_int = min;
      entry.max_int = max;
    }
    return Bind(
        std::move(entry),
        [access](Options& options) -> ConfigValue {
          return static_cast<BoundOf<Field>>(std::invoke(access, options));
        },
        [access](const ConfigValue& value, Options& options) {
          std::invoke(access, options) = static_cast<Field>(std::get<BoundOf<Field>>(value));
        });
  }

  template <typename Access>
  OptionsBinding& Bool(const std::string& key, Access access, const std::string& doc) {
    return Bind(
        NewEntry(key, doc),
        [access](Options& options) -> ConfigValue { return std::invoke(access, options); },
        [access](const ConfigValue& value, Options& options) {
          std::invoke(access, options) = std::get<bool>(value);
        });
  }

  /// A field constructible from and convertible to std::string (a string, a path); choices
  /// (empty: any text) restrict it.
  template <typename Access>
  OptionsBinding& Text(const std::string& key, Access access, const std::string& doc,
                       std::vector<std::string> choices = {}) {
    using Field = FieldOf<Access>;
    return Coded(
        key, access, doc,
        TextCodec<Field>{[](const Field& field) { return static_cast<std::string>(field); },
                         [](const std::string& text) { return static_cast<Field>(text); }},
        std::move(choices));
  }

  /// A field of any type, configured as the text `codec` reads and writes.
  template <typename Access, typename Field = FieldOf<Access>>
  OptionsBinding& Coded(const std::string& key, Access access, const std::string& doc,
                        TextCodec<Field> codec, std::vector<std::string> choices = {}) {
    ConfigSchema::Entry entry = NewEntry(key, doc);
    entry.choices = std::move(choices);
    return Bind(
        std::move(entry),
        [access, format = codec.format](Options& options) -> ConfigValue {
          return format(std::invoke(access, options));
        },
        [access, parse = codec.parse](const ConfigValue& value, Options& options) {
          std::invoke(access, options) = parse(std::get<std::string>(value));
        });
  }

  /// Every key of `inner`, in its order, bound to the field `access` of these options. The
  /// defaults are those of this binding's default options.
  template <typename Inner, typename Access>
  OptionsBinding& Include(const OptionsBinding<Inner>& inner, Access access) {
    for (const auto& key : inner.keys_) {
      Bind(
          key.entry,
          [access, get = key.get](Options& options) { return get(std::invoke(access, options)); },
          [access, set = key.set](const ConfigValue& value, Options& options) {
            set(value, std::invoke(access, options));
          });
    }
    for (const auto& check : inner.checks_) {
      checks_.push_back([access, check](Options& options) { check(std::invoke(access, options)); });
    }
    return *this;
  }

  /// Runs after every key is read: consistency checks between keys (a UserError) and fields that
  /// follow from others.
  OptionsBinding& Then(std::function<void(Options&)> check) {
    checks_.push_back(std::move(check));
    return *this;
  }

  /// The keys in declaration order, with the default options' values as defaults.
  ConfigSchema Schema() const {
    ConfigSchema schema;
    Options defaults = defaults_;
    for (const Key& key : keys_) {
      ConfigSchema::Entry entry = key.entry;
      entry.default_value = key.get(defaults);
      schema.Add(std::move(entry));
    }
    return schema;
  }

  /// The default options with every key's value of `config` (which declared Schema()), then the
  /// Then checks.
  Options Read(const Config& config) const {
    Options options = defaults_;
    for (const Key& key : keys_) key.set(config.Value(key.entry.key), options);
    for (const auto& check : checks_) check(options);
    return options;
  }

 private:
  template <typename>
  friend class OptionsBinding;

  struct Key {
    ConfigSchema::Entry entry;  // without its default
    std::function<ConfigValue(Options&)> get;
    std::function<void(const ConfigValue&, Options&)> set;
  };

  static ConfigSchema::Entry NewEntry(const std::string& key, const std::string& doc) {
    ConfigSchema::Entry entry;
    entry.key = key;
    entry.doc = doc;
    return entry;
  }

  OptionsBinding& Bind(ConfigSchema::Entry entry, std::function<ConfigValue(Options&)> get,
                       std::function<void(const ConfigValue&, Options&)> set) {
    keys_.push_back({std::move(entry), std::move(get), std::move(set)});
    try {
      Schema();  // a duplicate key or a default out of range fails here, at the declaration
    } catch (...) {
      keys_.pop_back();
      throw;
    }
    return *this;
  }

  Options defaults_;
  std::vector<Key> keys_;
  std::vector<std::function<void(Options&)>> checks_;
};

}  // namespace colav

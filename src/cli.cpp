#include "src/cli.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <iostream>
#include <map>
#include <stdexcept>

#include "src/error.h"

namespace colav {
namespace {

std::string& CurrentProgramName() {
  static std::string name = "colav";
  return name;
}

// The first line that says something: TorchScript's compilation errors start with a line break.
std::string FirstLine(const std::string& text) {
  const std::size_t start = std::min(text.find_first_not_of('\n'), text.size());
  return text.substr(start, text.find('\n', start) - start);
}

// What a flag's value looks like in --help.
std::string TypeNameOf(const ConfigSchema::Entry& entry) {
  const ConfigValue& value = entry.default_value;
  if (std::holds_alternative<double>(value)) return "NUMBER";
  if (std::holds_alternative<std::int64_t>(value)) return "INT";
  if (std::holds_alternative<bool>(value)) return "true|false";
  return entry.choices.empty() ? "TEXT" : fmt::format("{}", fmt::join(entry.choices, "|"));
}

// Lock-free, hence safe to set from a signal handler.
std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

void HandleStopSignal(int signal_number) {
  if (stop_requested.exchange(true)) {
    // Second signal: the user means it. Re-raised with the default action once this returns.
    signal(signal_number, SIG_DFL);
    raise(signal_number);
    return;
  }
  static constexpr char kMessage[] = "\nstopping cleanly; send the signal again to abort\n";
  [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, kMessage, sizeof(kMessage) - 1);
}

}  // namespace

int RunProgram(const std::string& program, int argc, char** argv,
               const std::function<int(int, char**)>& body) {
  CurrentProgramName() = program;
  try {
    return body(argc, argv);
  } catch (const UserError& e) {
    std::cerr << program << ": error: " << FirstLine(e.what()) << '\n';
    return 2;
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return 0;  // --help, printed by ParseCommandLine
    // A bad command line is bad input like any other: status 2, whatever CLI11's own code.
    std::cerr << program << ": error: " << FirstLine(e.what()) << " (see --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": internal error: " << FirstLine(e.what()) << '\n';
    return 1;
  } catch (...) {
    std::cerr << program << ": internal error: unknown exception\n";
    return 1;
  }
}

const std::string& ProgramName() { return CurrentProgramName(); }

void ParseCommandLine(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    app.exit(e);  // prints the help (or version)
    throw;
  }
}

ConfigFlags::ConfigFlags(CLI::App& app, const ConfigSchema& schema)
    : app_(app),
      schema_(schema),
      config_option_(app.add_option("--config", CLI::callback_t(),
                                    "YAML file of configuration keys (listed below)")),
      set_option_(app.add_option("--set", CLI::callback_t(),
                                 "override one configuration key (repeatable)")) {
  config_option_->type_name("FILE.yaml")->expected(1);
  set_option_->type_name("KEY=VALUE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  if (!schema_.entries().empty()) {
    app.footer(app.get_footer() + "\nConfiguration keys (KEY = DEFAULT (TYPE) DOC):\n" +
               schema_.Describe());
  }
  // A callback, because callbacks run before CLI11 checks required options.
  app.add_flag_callback(
      "--print-config",
      [this] {
        std::cout << ConfigYamlFile(Resolve());
        throw CLI::Success();
      },
      "print the resolved configuration (defaults, --config, --set, flags) as YAML and exit");
}

CLI::Option* ConfigFlags::AddFlag(const std::string& flag, const std::string& key) {
  const ConfigSchema::Entry* entry = schema_.Find(key);
  if (entry == nullptr) throw std::invalid_argument("ConfigFlags: undeclared key '" + key + "'");
  CLI::Option* option = app_.add_option(flag, CLI::callback_t(), entry->doc + " (" + key + ")");
  option->type_name(TypeNameOf(*entry))
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  shortcuts_.push_back({option, key, ""});
  return option;
}

CLI::Option* ConfigFlags::AddSwitch(const std::string& flag, const std::string& key, bool value,
                                    const std::string& doc) {
  const ConfigSchema::Entry* entry = schema_.Find(key);
  if (entry == nullptr || !std::holds_alternative<bool>(entry->default_value)) {
    throw std::invalid_argument("ConfigFlags: '" + key + "' is not a declared bool key");
  }
  const std::string value_text = value ? "true" : "false";
  const std::string description = doc + " (" + key + "=" + value_text + ")";
  CLI::Option* option = app_.add_flag(flag, description);
  shortcuts_.push_back({option, key, value_text});
  return option;
}

void ConfigFlags::RequireCompatibleSwitches() const {
  std::map<std::string, const Shortcut*> given;  // key -> the first switch given for it
  for (const Shortcut& shortcut : shortcuts_) {
    if (shortcut.switch_value.empty() || shortcut.option->count() == 0) continue;
    const auto [first, inserted] = given.emplace(shortcut.key, &shortcut);
    if (!inserted && first->second->switch_value != shortcut.switch_value) {
      throw UserError(first->second->option->get_name() + " and " + shortcut.option->get_name() +
                      " exclude each other");
    }
  }
}

Config ConfigFlags::Resolve() const {
  RequireCompatibleSwitches();
  const std::string config_path =
      config_option_->count() > 0 ? config_option_->results().back() : "";
  Config config = Config::Load(schema_, config_path, set_option_->results());
  // Shortcut flags in command-line order: the last of two --steps wins.
  std::map<const CLI::Option*, std::size_t> occurrences;
  for (const CLI::Option* option : app_.parse_order()) {
    const auto shortcut = std::find_if(shortcuts_.begin(), shortcuts_.end(),
                                       [&](const Shortcut& s) { return s.option == option; });
    if (shortcut == shortcuts_.end()) continue;
    const std::size_t occurrence = occurrences[option]++;
    const std::string value =
        shortcut->switch_value.empty() ? option->results().at(occurrence) : shortcut->switch_value;
    config.Set(shortcut->key, value, option->get_name());
  }
  return config;
}

std::string ConfigYamlFile(const Config& config) {
  return "# " + ProgramName() + " configuration (" + ProgramName() +
         " --print-config); read with --config FILE.yaml.\n" + config.ToDocumentedYaml();
}

StopFlag::StopFlag() {
  stop_requested = false;
  struct sigaction action {};
  action.sa_handler = HandleStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // interrupted reads and writes resume instead of failing
  sigaction(SIGINT, &action, &previous_interrupt_);
  sigaction(SIGTERM, &action, &previous_terminate_);
}

StopFlag::~StopFlag() {
  sigaction(SIGINT, &previous_interrupt_, nullptr);
  sigaction(SIGTERM, &previous_terminate_, nullptr);
}

bool StopFlag::StopRequested() { return stop_requested; }

}  // namespace colav

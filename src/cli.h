// Command-line plumbing shared by every program: uniform error reporting and exit codes, the
// common --config / --set / --print-config flags resolved into a Config, and clean stopping on
// Ctrl-C. A program turns the Config into its typed options once, in main (OptionsBinding):
//
//   int main(int argc, char** argv) {
//     return colav::RunProgram("train_ppo", argc, argv, [](int argc, char** argv) {
//       CLI::App app{"Trains the PPO agent."};
//       const colav::OptionsBinding<colav::PpoRunOptions> binding = colav::PpoRunBinding();
//       colav::ConfigFlags config_flags(app, binding.Schema());
//       config_flags.AddFlag("--steps", "ppo.total_steps");
//       colav::ParseCommandLine(app, argc, argv);
//       const colav::PpoRunOptions options = binding.Read(config_flags.Resolve());
//       ...
//     });
//   }
#pragma once

#include <signal.h>

#include <functional>
#include <string>
#include <vector>

#include "src/config.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace colav {

/// Runs `body(argc, argv)` and returns its exit status, turning escaping exceptions into one line
/// on stderr: colav::UserError and CLI::ParseError (a bad command line) -> "<program>: error:
/// <message>", status 2 (--help: status 0, nothing printed here); anything else -> "<program>:
/// internal error: <message>", status 1, which is a bug. Only the first line of a message is
/// printed (LibTorch errors append a backtrace).
int RunProgram(const std::string& program, int argc, char** argv,
               const std::function<int(int, char**)>& body);

/// The program name given to the running RunProgram ("colav" outside one).
const std::string& ProgramName();

/// Parses the command line into `app`. --help prints the help and throws the CLI::Success that
/// RunProgram turns into exit status 0; a bad command line throws CLI::ParseError.
void ParseCommandLine(CLI::App& app, int argc, char** argv);

/// The flags that feed a Config: --config FILE.yaml, repeatable --set key=value, shortcut flags
/// for single keys, and --print-config. `app` must outlive this object.
class ConfigFlags {
 public:
  /// Adds --config, --set and --print-config to `app`, and the schema's keys to its help.
  /// --print-config prints the resolved configuration (ConfigYamlFile) and ends the program with
  /// status 0 while parsing, before required options are checked.
  ConfigFlags(CLI::App& app, const ConfigSchema& schema);
  ConfigFlags(const ConfigFlags&) = delete;
  ConfigFlags& operator=(const ConfigFlags&) = delete;

  /// Adds `flag VALUE` (e.g. "--steps") meaning --set key=VALUE, documented by the key's doc.
  CLI::Option* AddFlag(const std::string& flag, const std::string& key);
  /// Adds a flag without value that sets bool `key` to `value` (e.g. --locked / --unlocked); two
  /// switches setting the same key to different values exclude each other.
  CLI::Option* AddSwitch(const std::string& flag, const std::string& key, bool value,
                         const std::string& doc);

  /// After parsing: the schema defaults, then the --config file, then the --set overrides in
  /// order, then the shortcut flags in command-line order. Bad input is a colav::UserError.
  Config Resolve() const;

 private:
  struct Shortcut {
    CLI::Option* option;
    std::string key;
    std::string switch_value;  // "" for a flag with a value
  };

  CLI::App& app_;
  ConfigSchema schema_;
  CLI::Option* config_option_;
  CLI::Option* set_option_;
  std::vector<Shortcut> shortcuts_;

  /// UserError when switches given together set one key to different values.
  void RequireCompatibleSwitches() const;
};

/// The configuration as a file for --config: a comment naming the running program, then
/// Config::ToDocumentedYaml. configs/<program>.yaml holds each program's defaults in this form.
std::string ConfigYamlFile(const Config& config);

/// Turns SIGINT and SIGTERM into a request to stop, so that a training loop can checkpoint and
/// exit cleanly; a second signal ends the program at once. Installs the handlers for its lifetime
/// (one StopFlag at a time), restoring the previous ones afterwards.
class StopFlag {
 public:
  StopFlag();
  StopFlag(const StopFlag&) = delete;
  StopFlag& operator=(const StopFlag&) = delete;
  ~StopFlag();

  /// True once SIGINT or SIGTERM has arrived.
  static bool StopRequested();

 private:
  struct sigaction previous_interrupt_ {};
  struct sigaction previous_terminate_ {};
};

}  // namespace colav

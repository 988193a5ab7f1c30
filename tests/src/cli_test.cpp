#include "src/cli.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdlib>
#include <stdexcept>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::HasSubstr;
using ::testing::MatchesRegex;
using testing_util::Argv;
using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;

struct Outcome {
  int status;
  std::string stderr_text;
};

// Runs `body` through RunProgram("prog", ...) with `arguments` (argv[0] included).
Outcome RunCaptured(const std::function<int(int, char**)>& body,
                    std::vector<std::string> arguments = {"prog"}) {
  std::vector<char*> argv = Argv(arguments);
  ::testing::internal::CaptureStderr();
  const int status = RunProgram("prog", static_cast<int>(arguments.size()), argv.data(), body);
  return {status, ::testing::internal::GetCapturedStderr()};
}

TEST(RunProgramTest, PassesTheBodysStatusThrough) {
  const Outcome outcome = RunCaptured([](int, char**) { return 3; });
  EXPECT_EQ(outcome.status, 3);
  EXPECT_EQ(outcome.stderr_text, "");
}

TEST(RunProgramTest, UserErrorPrintsOneLineAndReturnsTwo) {
  const Outcome outcome =
      RunCaptured([](int, char**) -> int { throw UserError("data.h5: no such file"); });
  EXPECT_EQ(outcome.status, 2);
  EXPECT_EQ(outcome.stderr_text, "prog: error: data.h5: no such file\n");
}

TEST(RunProgramTest, OtherExceptionsAreInternalErrorsWithStatusOne) {
  const Outcome outcome =
      RunCaptured([](int, char**) -> int { throw std::logic_error("broken\nbacktrace..."); });
  EXPECT_EQ(outcome.status, 1);
  EXPECT_EQ(outcome.stderr_text, "prog: internal error: broken\n");
}

TEST(RunProgramTest, NonStandardExceptionsAreInternalErrors) {
  const Outcome outcome = RunCaptured([](int, char**) -> int { throw 42; });
  EXPECT_EQ(outcome.status, 1);
  EXPECT_EQ(outcome.stderr_text, "prog: internal error: unknown exception\n");
}

TEST(RunProgramTest, RecordsTheProgramName) {
  std::string seen;
  RunCaptured([&](int, char**) {
    seen = ProgramName();
    return 0;
  });
  EXPECT_EQ(seen, "prog");
}

int ParseOnly(int argc, char** argv) {
  CLI::App app{"A test program."};
  int count = 0;
  app.add_option("--count", count, "a number")->required();
  ParseCommandLine(app, argc, argv);
  return count;
}

TEST(RunProgramTest, BadCommandLineIsOneLineWithStatusTwo) {
  const Outcome extra = RunCaptured(ParseOnly, {"prog", "--count", "3", "--bogus"});
  EXPECT_EQ(extra.status, 2);
  EXPECT_THAT(extra.stderr_text, MatchesRegex("prog: error: .*--bogus.*\n"));
  const Outcome missing = RunCaptured(ParseOnly, {"prog"});
  EXPECT_EQ(missing.status, 2);
  EXPECT_THAT(missing.stderr_text, MatchesRegex("prog: error: .*--count.*\n"));
  const Outcome no_value = RunCaptured(ParseOnly, {"prog", "--count"});
  EXPECT_EQ(no_value.status, 2);
  EXPECT_THAT(no_value.stderr_text, MatchesRegex("prog: error: .*--count.*\n"));
}

TEST(RunProgramTest, HelpPrintsUsageAndReturnsZero) {
  ::testing::internal::CaptureStdout();
  const Outcome outcome = RunCaptured(ParseOnly, {"prog", "--help"});
  const std::string help = ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(outcome.status, 0);
  EXPECT_THAT(help, HasSubstr("--count"));
  EXPECT_EQ(outcome.stderr_text, "");
}

ConfigSchema FlagSchema() {
  ConfigSchema schema;
  schema.AddInt("ppo.total_steps", 100, "environment steps", 1)
      .AddDouble("ppo.learning_rate", 2e-4, "Adam learning rate", 0, 1)
      .AddBool("extractor.locked", true, "freeze the encoder");
  return schema;
}

// Parses `arguments` with ConfigFlags over FlagSchema and returns the resolved Config.
Config Resolve(std::vector<std::string> arguments) {
  CLI::App app{"test"};
  ConfigFlags flags(app, FlagSchema());
  flags.AddFlag("--steps", "ppo.total_steps");
  flags.AddSwitch("--locked", "extractor.locked", true, "freeze the encoder");
  flags.AddSwitch("--unlocked", "extractor.locked", false, "train the encoder");
  std::vector<char*> argv = Argv(arguments);
  ParseCommandLine(app, static_cast<int>(arguments.size()), argv.data());
  return flags.Resolve();
}

TEST(ConfigFlagsTest, DefaultsWithoutFlags) {
  const Config config = Resolve({"prog"});
  EXPECT_EQ(config.GetInt("ppo.total_steps"), 100);
  EXPECT_TRUE(config.GetBool("extractor.locked"));
}

TEST(ConfigFlagsTest, FlagsBeatSetsBeatFileBeatsDefaults) {
  TemporaryFolder folder;
  const std::string yaml = (folder / "c.yaml").string();
  testing_util::WriteFile(yaml, "ppo: {total_steps: 5, learning_rate: 0.5}\n");
  const Config config = Resolve({"prog", "--steps", "7", "--set", "ppo.total_steps=6", "--set",
                                 "ppo.learning_rate=0.25", "--config", yaml});
  EXPECT_EQ(config.GetInt("ppo.total_steps"), 7);
  EXPECT_DOUBLE_EQ(config.GetDouble("ppo.learning_rate"), 0.25);
}

TEST(ConfigFlagsTest, SwitchesSetTheirKey) {
  EXPECT_FALSE(Resolve({"prog", "--unlocked"}).GetBool("extractor.locked"));
  EXPECT_TRUE(
      Resolve({"prog", "--set", "extractor.locked=false", "--locked"}).GetBool("extractor.locked"));
  EXPECT_TRUE(Resolve({"prog", "--locked", "--locked"}).GetBool("extractor.locked"));
}

TEST(ConfigFlagsTest, OpposingSwitchesExcludeEachOther) {
  EXPECT_EQ(UserErrorMessage([] {
              Resolve({"prog", "--locked", "--unlocked"});
            }),
            "--locked and --unlocked exclude each other");
  EXPECT_EQ(UserErrorMessage([] {
              Resolve({"prog", "--unlocked", "--locked"});
            }),
            "--locked and --unlocked exclude each other");
}

TEST(ConfigFlagsTest, BadFlagValueNamesTheFlagAndKey) {
  EXPECT_EQ(UserErrorMessage([] {
              Resolve({"prog", "--steps", "lots"});
            }),
            "--steps: key 'ppo.total_steps' expects an integer, got 'lots'");
  EXPECT_EQ(UserErrorMessage([] {
              Resolve({"prog", "--set", "ppo.total_steps=0"});
            }),
            "--set: key 'ppo.total_steps' = 0 is out of range [1, inf)");
  EXPECT_EQ(UserErrorMessage([] {
              Resolve({"prog", "--config", "missing.yaml"});
            }),
            "missing.yaml: no such file");
}

TEST(ConfigFlagsTest, HelpListsTheConfigurationKeys) {
  CLI::App app{"test"};
  ConfigFlags flags(app, FlagSchema());
  flags.AddFlag("--steps", "ppo.total_steps");
  const std::string help = app.help();
  EXPECT_THAT(help, HasSubstr("ppo.learning_rate = 0.0002 (double in [0, 1]) Adam learning rate"));
  EXPECT_THAT(help, HasSubstr("environment steps (ppo.total_steps)"));
  EXPECT_THROW(flags.AddFlag("--nope", "ppo.nope"), std::invalid_argument);
  EXPECT_THROW(flags.AddSwitch("--fast", "ppo.learning_rate", true, "not a bool"),
               std::invalid_argument);
}

// Runs a program with a required --out and ConfigFlags over FlagSchema; returns its stdout.
std::string RunPrintingConfig(std::vector<std::string> arguments, int expected_status) {
  std::vector<char*> argv = Argv(arguments);
  ::testing::internal::CaptureStdout();
  const int status = RunProgram("prog", static_cast<int>(arguments.size()), argv.data(),
                                [](int argc, char** argv) {
                                  CLI::App app{"test"};
                                  std::string out;
                                  app.add_option("--out", out, "required")->required();
                                  ConfigFlags flags(app, FlagSchema());
                                  flags.AddFlag("--steps", "ppo.total_steps");
                                  ParseCommandLine(app, argc, argv);
                                  return 7;  // not reached with --print-config
                                });
  EXPECT_EQ(status, expected_status);
  return ::testing::internal::GetCapturedStdout();
}

TEST(ConfigFlagsTest, PrintConfigPrintsTheResolvedConfigurationAndExitsZero) {
  const std::string printed = RunPrintingConfig(
      {"prog", "--set", "ppo.learning_rate=0.5", "--print-config", "--steps", "9"}, 0);
  EXPECT_EQ(printed,
            "# prog configuration (prog --print-config); read with --config FILE.yaml.\n"
            "ppo:\n"
            "  total_steps: 9  # environment steps\n"
            "  learning_rate: 0.5  # Adam learning rate\n"
            "extractor:\n"
            "  locked: true  # freeze the encoder\n");
  EXPECT_EQ(RunPrintingConfig({"prog", "--out", "x"}, 7), "");
}

TEST(ConfigFlagsTest, PrintConfigReportsBadValues) {
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(RunPrintingConfig({"prog", "--print-config", "--steps", "0"}, 2), "");
  EXPECT_THAT(::testing::internal::GetCapturedStderr(), HasSubstr("out of range"));
}

TEST(StopFlagTest, SignalsRequestAStop) {
  {
    StopFlag stop;
    EXPECT_FALSE(StopFlag::StopRequested());
    std::raise(SIGTERM);
    EXPECT_TRUE(StopFlag::StopRequested());
  }
  StopFlag again;  // a new flag starts cleared
  EXPECT_FALSE(StopFlag::StopRequested());
  ::testing::internal::CaptureStderr();
  std::raise(SIGINT);
  EXPECT_THAT(::testing::internal::GetCapturedStderr(), HasSubstr("stopping cleanly"));
  EXPECT_TRUE(StopFlag::StopRequested());
}

void CountSignal(int) {}

TEST(StopFlagTest, RestoresThePreviousHandlers) {
  struct sigaction counting {};
  counting.sa_handler = CountSignal;
  struct sigaction saved {};
  sigaction(SIGINT, &counting, &saved);
  { StopFlag stop; }
  struct sigaction current {};
  sigaction(SIGINT, nullptr, &current);
  EXPECT_EQ(current.sa_handler, &CountSignal);
  sigaction(SIGINT, &saved, nullptr);
}

TEST(StopFlagDeathTest, SecondSignalEndsTheProgram) {
  EXPECT_EXIT(
      {
        StopFlag stop;
        std::raise(SIGINT);
        std::raise(SIGINT);
        std::exit(0);
      },
      ::testing::KilledBySignal(SIGINT), "");
}

}  // namespace
}  // namespace colav

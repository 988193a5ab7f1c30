// The evaluate program end to end on tiny policies: outputs, determinism, one-line errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/eval/test_policies.h"
#include "tests/src/project_paths.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::ReadFile;
using testing_util::TemporaryFolder;
namespace tp = testing_policies;

struct CommandResult {
  int status = -1;
  std::string out;
  std::string err;
};

// Runs build/bin/evaluate with `arguments` (shell words, already quoted where needed).
CommandResult RunEvaluate(const std::string& arguments, const TemporaryFolder& folder) {
  const char* bin_dir = std::getenv("COLAV_BIN_DIR");
  const std::string program =
      (bin_dir != nullptr ? std::string(bin_dir) : std::string(testing_util::kBinaryDir) + "/bin") +
      "/evaluate";
  const std::string command = program + " " + arguments + " > " + (folder / "out.txt").string() +
                              " 2> " + (folder / "err.txt").string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ReadFile(folder / "out.txt"),
          ReadFile(folder / "err.txt")};
}

class EvaluateProgramTest : public ::testing::Test {
 protected:
  void SetUp() override {
    tp::SavePolicy(tp::ReactivePolicy(1), folder_ / "reactive.pt");
    tp::SavePolicy(tp::ConstantThrustPolicy(), folder_ / "constant.pt");
  }
  std::string Path(const std::string& name) const { return (folder_ / name).string(); }
  // A quick evaluation of both policies on three test scenarios.
  CommandResult EvaluateBoth(const std::string& out) {
    return RunEvaluate("--policy " + Path("reactive.pt") + " --policy " + Path("constant.pt") +
                           " --episodes 3 --trajectories 1 --trajectory-starts 2 --set "
                           "env.max_steps=300 --out " +
                           Path(out),
                       folder_);
  }
  TemporaryFolder folder_;
};

TEST_F(EvaluateProgramTest, WritesTablesAndFiguresDeterministically) {
  const CommandResult first = EvaluateBoth("first");
  ASSERT_EQ(first.status, 0) << first.err;
  for (const char* file : {"episodes.csv", "summary.json", "summary.md", "config.yaml",
                           "figures/test-000_reactive.png", "figures/test-000_constant.png"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(folder_ / "first" / file)) << file;
  }
  const std::string csv = ReadFile(folder_ / "first" / "episodes.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 3) << csv;
  EXPECT_NE(csv.find("\nconstant,test-002,"), std::string::npos) << csv;
  const auto summary = nlohmann::json::parse(ReadFile(folder_ / "first" / "summary.json"));
  EXPECT_EQ(summary["models"].size(), 2U);
  EXPECT_EQ(summary["paired_differences"][0]["first"], "reactive");
  EXPECT_EQ(summary["models"][1]["metrics"]["progress"]["n"], 3);
  EXPECT_NE(first.out.find("wall_s: "), std::string::npos);
  EXPECT_EQ(ReadFile(folder_ / "first" / "config.yaml").find("test_mode: false"),
            std::string::npos);

  const CommandResult second = EvaluateBoth("second");
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_EQ(csv, ReadFile(folder_ / "second" / "episodes.csv"));
}

TEST_F(EvaluateProgramTest, ScenarioFilesGiveAPicturePerScenarioAndModel) {
  const std::string scenarios = std::string(testing_util::kSourceDir) + "/configs/scenarios/";
  const CommandResult result =
      RunEvaluate("--policy " + Path("reactive.pt") + " --name steer --scenario " + scenarios +
                      "head-on.yaml --scenario " + scenarios +
                      "narrow-gap.yaml --set env.max_steps=200 --out " + Path("files"),
                  folder_);
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(folder_ / "files/figures/head-on_steer.png"));
  EXPECT_TRUE(std::filesystem::is_regular_file(folder_ / "files/figures/narrow-gap_steer.png"));
  const std::string csv = ReadFile(folder_ / "files" / "episodes.csv");
  EXPECT_NE(csv.find("\nsteer,head-on,,"), std::string::npos) << csv;
}

// Exit status 2 and exactly one line on stderr, naming the file.
void ExpectOneLineError(const CommandResult& result, const std::string& expected_start) {
  EXPECT_EQ(result.status, 2) << result.err;
  EXPECT_EQ(result.err.rfind("evaluate: error: " + expected_start, 0), 0U) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

TEST_F(EvaluateProgramTest, BadPolicyFilesAreOneLineErrors) {
  testing_util::WriteFile(folder_ / "corrupt.pt", "not TorchScript");
  tp::SavePolicy(tp::WrongObservationSizePolicy(), folder_ / "small.pt");
  for (const std::string name : {"missing.pt", "corrupt.pt", "small.pt"}) {
    SCOPED_TRACE(name);
    ExpectOneLineError(RunEvaluate("--policy " + Path("reactive.pt") + " --policy " + Path(name) +
                                       " --out " + Path("bad"),
                                   folder_),
                       Path(name) + ": ");
  }
  EXPECT_FALSE(std::filesystem::exists(folder_ / "bad"));
}

TEST_F(EvaluateProgramTest, BadArgumentsAreOneLineErrors) {
  ExpectOneLineError(RunEvaluate("--policy " + Path("reactive.pt") + " --policy " +
                                     Path("reactive.pt") + " --out " + Path("dup"),
                                 folder_),
                     Path("reactive.pt") + ": model name 'reactive' is already used");
  ExpectOneLineError(
      RunEvaluate("--policy " + Path("reactive.pt") + " --name a --name b --out " + Path("names"),
                  folder_),
      "--name: 2 names for 1 policies");
  ExpectOneLineError(RunEvaluate("--policy " + Path("reactive.pt") + " --scenario " +
                                     Path("nowhere.yaml") + " --out " + Path("noscenario"),
                                 folder_),
                     Path("nowhere.yaml"));
  ExpectOneLineError(RunEvaluate("--policy " + Path("reactive.pt") + " --reuse " + Path("x") +
                                     " --out " + Path("reuse_figures"),
                                 folder_),
                     "--reuse takes episodes without their runs");
}

// --reuse takes an earlier evaluation's episodes of a model whose file is unchanged, runs the
// others, and writes what a full evaluation writes; a changed file is run again.
TEST_F(EvaluateProgramTest, ReusedEpisodesGiveTheOutputsOfAFullRun) {
  const std::string both = "--policy " + Path("reactive.pt") + " --policy " + Path("constant.pt");
  const std::string settings = " --episodes 3 --trajectories 0 --set env.max_steps=300";
  ASSERT_EQ(RunEvaluate(both + settings + " --out " + Path("full"), folder_).status, 0);
  ASSERT_EQ(
      RunEvaluate("--policy " + Path("reactive.pt") + settings + " --out " + Path("grown"), folder_)
          .status,
      0);
  // The study's way: the same folder grows by a model, reusing itself.
  const CommandResult grown = RunEvaluate(
      both + settings + " --reuse " + Path("grown") + " --out " + Path("grown") + " --overwrite",
      folder_);
  ASSERT_EQ(grown.status, 0) << grown.err;
  for (const char* file : {"episodes.csv", "summary.json", "summary.md", "config.yaml"}) {
    EXPECT_EQ(ReadFile(folder_ / "grown" / file), ReadFile(folder_ / "full" / file)) << file;
  }
  const std::string log = ReadFile(folder_ / "grown" / "evaluate.log");
  EXPECT_NE(log.find("--reuse: the episodes of 1 of 2 model(s) taken from " + Path("grown") +
                     " (same settings, scenarios and policy files): reactive"),
            std::string::npos)
      << log;
  // A policy file replaced under the same name is run again, not taken.
  tp::SavePolicy(tp::ReactivePolicy(2), folder_ / "reactive.pt");
  const CommandResult changed = RunEvaluate(
      both + settings + " --reuse " + Path("full") + " --out " + Path("changed"), folder_);
  ASSERT_EQ(changed.status, 0) << changed.err;
  const std::string changed_log = ReadFile(folder_ / "changed" / "evaluate.log");
  EXPECT_NE(changed_log.find("the episodes of 1 of 2 model(s) taken from " + Path("full") +
                             " (same settings, scenarios and policy files): constant"),
            std::string::npos)
      << changed_log;
  ASSERT_EQ(RunEvaluate(both + settings + " --out " + Path("changed_full"), folder_).status, 0);
  EXPECT_EQ(ReadFile(folder_ / "changed" / "episodes.csv"),
            ReadFile(folder_ / "changed_full" / "episodes.csv"));
}

}  // namespace
}  // namespace colav

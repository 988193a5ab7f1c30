#include "src/run_folder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <memory>

#include "src/cli.h"
#include "src/error.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::StartsWith;
using testing_util::TemporaryFolder;

TEST(RunFolderTest, CreatesNestedFoldersAndReusesExistingOnes) {
  TemporaryFolder folder;
  const RunFolder run = RunFolder::Create(folder / "runs/a/b", "train_vae");
  EXPECT_TRUE(std::filesystem::is_directory(folder / "runs/a/b"));
  EXPECT_EQ(run.path(), folder / "runs/a/b");
  EXPECT_EQ(run.LogPath(), folder / "runs/a/b/train_vae.log");
}

TEST(RunFolderTest, ExistingFolderIsReusedOnceItsHolderLetsGo) {
  TemporaryFolder folder;
  { const RunFolder first = RunFolder::Create(folder / "run", "train_vae"); }
  EXPECT_NO_THROW(RunFolder::Create(folder / "run", "train_vae"));
}

TEST(RunFolderTest, FolderInUseIsRefusedNamingItsHolder) {
  TemporaryFolder folder;
  const RunFolder holder = RunFolder::Create(folder / "run", "train_ppo");
  const std::string message =
      testing_util::UserErrorMessage([&] { RunFolder::Create(folder / "run", "train_ppo"); });
  EXPECT_THAT(message,
              StartsWith((folder / "run").string() + ": run folder in use by train_ppo, pid " +
                         std::to_string(getpid()) + " on host "));
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(RunFolderTest, CopiesHoldTheLockUntilTheLastGoes) {
  TemporaryFolder folder;
  auto holder = std::make_unique<RunFolder>(RunFolder::Create(folder / "run", "a"));
  const RunFolder copy = *holder;  // copies share the lock
  holder.reset();
  EXPECT_THROW(RunFolder::Create(folder / "run", "b"), UserError);
}

TEST(RunFolderTest, NewRunRefusesAFolderHoldingARunWithoutOverwrite) {
  TemporaryFolder folder;
  const RunFolder run = RunFolder::Create(folder.path(), "train_ppo");
  testing_util::WriteFile(folder / "summary.json", "{}");
  testing_util::WriteFile(folder / "episodes.csv", "x");
  const std::string message = testing_util::UserErrorMessage([&] {
    run.StartNewRun({"training_state.pt", "summary.json"}, {"summary.json", "episodes.csv"}, false,
                    "use --overwrite");
  });
  EXPECT_EQ(message, folder.path().string() + " holds a run (summary.json): use --overwrite");
  EXPECT_TRUE(std::filesystem::exists(folder / "episodes.csv"));  // refused: nothing removed
  run.StartNewRun({"training_state.pt", "summary.json"}, {"summary.json", "episodes.csv"}, true,
                  "use --overwrite");
  EXPECT_FALSE(std::filesystem::exists(folder / "summary.json"));
  EXPECT_FALSE(std::filesystem::exists(folder / "episodes.csv"));
}

TEST(RunFolderTest, NewRunClearsTheOutputsOfAnUnfinishedStart) {
  TemporaryFolder folder;
  const RunFolder run = RunFolder::Create(folder.path(), "train_ppo");
  testing_util::WriteFile(folder / "episodes.csv", "x");
  run.StartNewRun({"training_state.pt"}, {"episodes.csv"}, false, "");
  EXPECT_FALSE(std::filesystem::exists(folder / "episodes.csv"));
}

ConfigSchema TwoKeys() {
  ConfigSchema schema;
  schema.AddInt("ppo.n_envs", 8, "worlds", 1, 100).AddInt("train.env_threads", 0, "threads", 0, 64);
  return schema;
}

TEST(RunFolderTest, ContinuedRunRefusesAChangedConfigurationNamingTheKey) {
  TemporaryFolder folder;
  const RunFolder run = RunFolder::Create(folder.path(), "train_ppo");
  run.WriteResolvedConfig(Config::Load(TwoKeys(), "", {"ppo.n_envs=2"}));
  EXPECT_NO_THROW(
      run.RequireConfigUnchanged(Config::Load(TwoKeys(), "", {"ppo.n_envs=2"}), TwoKeys()));
  EXPECT_EQ(testing_util::UserErrorMessage([&] {
              run.RequireConfigUnchanged(Config::Load(TwoKeys(), "", {"ppo.n_envs=4"}), TwoKeys());
            }),
            folder.path().string() + ": 'ppo.n_envs' = 4 differs from the run's 2 (" +
                (folder / "config.yaml").string() + "); a run continues with its configuration");
  const Config more_threads = Config::Load(TwoKeys(), "", {"ppo.n_envs=2", "train.env_threads=3"});
  EXPECT_THROW(run.RequireConfigUnchanged(more_threads, TwoKeys()), UserError);
  EXPECT_NO_THROW(run.RequireConfigUnchanged(more_threads, TwoKeys(), {"train.env_threads"}));
}

TEST(RunFolderTest, ContinuedRunIsCheckedAgainstTheRecordedConfigurationNotItsFile) {
  TemporaryFolder folder;
  const RunFolder run = RunFolder::Create(folder.path(), "train_ppo");
  // config.yaml edited by hand after the run started: the record in the state file decides.
  run.WriteResolvedConfig(Config::Load(TwoKeys(), "", {"ppo.n_envs=4"}));
  const Config recorded = Config::Load(TwoKeys(), "", {"ppo.n_envs=2"});
  const Config edited = Config::Load(TwoKeys(), (folder / "config.yaml").string());
  EXPECT_EQ(testing_util::UserErrorMessage(
                [&] { run.RequireConfigUnchanged(edited, recorded, "run/training_state.pt", {}); }),
            folder.path().string() +
                ": 'ppo.n_envs' = 4 differs from the run's 2 (run/training_state.pt); a run "
                "continues with its configuration");
  EXPECT_NO_THROW(run.RequireConfigUnchanged(recorded, recorded, "run/training_state.pt", {}));
  const Config more_threads = Config::Load(TwoKeys(), "", {"ppo.n_envs=2", "train.env_threads=3"});
  EXPECT_NO_THROW(
      run.RequireConfigUnchanged(more_threads, recorded, "state", {"train.env_threads"}));
}

TEST(RunFolderTest, LogIsNamedAfterTheRunningProgramByDefault) {
  TemporaryFolder folder;
  std::filesystem::path log;
  char name[] = "train_ppo";
  char* argv[] = {name, nullptr};
  RunProgram("train_ppo", 1, argv, [&](int, char**) {
    log = RunFolder::Create(folder / "run").LogPath();
    return 0;
  });
  EXPECT_EQ(log, folder / "run/train_ppo.log");
}

TEST(RunFolderTest, WritesTheResolvedConfigForReuse) {
  TemporaryFolder folder;
  ConfigSchema schema;
  schema.AddInt("ppo.n_epochs", 4, "epochs", 1, 100).AddString("vae.model", "shallow", "model");
  const Config config = Config::Load(schema, "", {"ppo.n_epochs=9"});
  RunFolder::Create(folder.path(), "prog").WriteResolvedConfig(config);
  const Config reloaded = Config::Load(schema, (folder / "config.yaml").string());
  EXPECT_EQ(reloaded.GetInt("ppo.n_epochs"), 9);
  EXPECT_EQ(reloaded.ToJson(), config.ToJson());
  std::vector<std::string> entries = folder.Entries();
  std::sort(entries.begin(), entries.end());
  EXPECT_EQ(entries, (std::vector<std::string>{".lock", "config.yaml"}));
}

TEST(RunFolderTest, FileInTheWayIsAUserErrorNamingIt) {
  TemporaryFolder folder;
  testing_util::WriteFile(folder / "taken", "x");
  EXPECT_THAT(testing_util::UserErrorMessage([&] { RunFolder::Create(folder / "taken", "p"); }),
              StartsWith((folder / "taken").string() + ": cannot create run folder ("));
}

TEST(RunFolderTest, DefaultPathIsUnderRuns) {
  EXPECT_EQ(RunFolder::DefaultPath("vae-shallow"), std::filesystem::path("runs/vae-shallow"));
}

}  // namespace
}  // namespace colav

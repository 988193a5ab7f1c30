#include "src/run_folder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/cli.h"
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
  EXPECT_NO_THROW(RunFolder::Create(folder / "runs/a/b", "train_vae"));
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
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{"config.yaml"});
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

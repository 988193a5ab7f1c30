#include "src/output_path.h"

#include <gtest/gtest.h>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;
using testing_util::WriteFile;

TEST(OutputPathTest, FilesUnderExistingOrCreatableFoldersAreAccepted) {
  TemporaryFolder folder;
  EXPECT_NO_THROW(RequireWritableFile(folder / "out.csv", "--out"));
  EXPECT_NO_THROW(RequireWritableFile(folder / "new/deeper/out.csv", "--out"));
  WriteFile(folder / "existing.csv", "old");
  EXPECT_NO_THROW(RequireWritableFile(folder / "existing.csv", "--out"));
  EXPECT_NO_THROW(RequireWritableFolder(folder / "new/run", "--out"));
  EXPECT_NO_THROW(RequireWritableFolder(folder.path(), "--out"));
  EXPECT_TRUE(folder.Entries().size() == 1) << "nothing is created";
}

TEST(OutputPathTest, RefusalsNameTheFlagAndThePath) {
  TemporaryFolder folder;
  WriteFile(folder / "file", "x");
  const std::string base = folder.path().string();
  EXPECT_EQ(UserErrorMessage([&] { RequireWritableFile(folder.path(), "--out"); }),
            "--out " + base + ": is a folder, not a file");
  EXPECT_EQ(UserErrorMessage([&] { RequireWritableFile(folder / "file/out.csv", "--plot"); }),
            "--plot " + base + "/file/out.csv: " + base + "/file is not a folder");
  EXPECT_EQ(UserErrorMessage([&] { RequireWritableFile("", "--out"); }), "--out: empty path");
  EXPECT_EQ(UserErrorMessage([&] { RequireWritableFolder(folder / "file", "--out"); }),
            "--out " + base + "/file: exists and is not a folder");
}

}  // namespace
}  // namespace colav

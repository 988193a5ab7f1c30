#include "src/atomic_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::ElementsAre;
using ::testing::StartsWith;
using testing_util::ReadFile;
using testing_util::TemporaryFolder;

TEST(AtomicFileTest, WritesContentAndLeavesNoTemporaryFile) {
  TemporaryFolder folder;
  WriteTextFileAtomically(folder / "out.txt", "hello\n");
  EXPECT_EQ(ReadFile(folder / "out.txt"), "hello\n");
  EXPECT_THAT(folder.Entries(), ElementsAre("out.txt"));
}

TEST(AtomicFileTest, ReplacesExistingContent) {
  TemporaryFolder folder;
  WriteTextFileAtomically(folder / "out.txt", "old content that is longer");
  WriteTextFileAtomically(folder / "out.txt", "new");
  EXPECT_EQ(ReadFile(folder / "out.txt"), "new");
}

TEST(AtomicFileTest, CreatesParentFolders) {
  TemporaryFolder folder;
  WriteTextFileAtomically(folder / "a/b/c.txt", "x");
  EXPECT_EQ(ReadFile(folder / "a/b/c.txt"), "x");
}

TEST(AtomicFileTest, CallbackWritesAHiddenTemporaryFileInTheSameFolder) {
  TemporaryFolder folder;
  std::filesystem::path seen;
  WriteFileAtomically(folder / "data.bin", [&](const std::filesystem::path& temporary) {
    seen = temporary;
    std::ofstream(temporary) << "payload";
  });
  EXPECT_EQ(seen.parent_path(), folder.path());
  EXPECT_THAT(seen.filename().string(), StartsWith(".data.bin.tmp-"));
  EXPECT_FALSE(std::filesystem::exists(seen));
  EXPECT_EQ(ReadFile(folder / "data.bin"), "payload");
}

TEST(AtomicFileTest, ExceptionKeepsOldContentRemovesTemporaryAndPropagates) {
  TemporaryFolder folder;
  WriteTextFileAtomically(folder / "out.txt", "old");
  const auto half_write_then_fail = [](const std::filesystem::path& temporary) {
    std::ofstream(temporary) << "half of the new";
    throw std::runtime_error("writer failed");
  };
  EXPECT_THROW(WriteFileAtomically(folder / "out.txt", half_write_then_fail), std::runtime_error);
  EXPECT_EQ(ReadFile(folder / "out.txt"), "old");
  EXPECT_THAT(folder.Entries(), ElementsAre("out.txt"));
}

TEST(AtomicFileTest, ExceptionBeforeAnyWriteLeavesNothing) {
  TemporaryFolder folder;
  EXPECT_THROW(WriteFileAtomically(folder / "never.txt",
                                   [](const std::filesystem::path&) { throw UserError("no"); }),
               UserError);
  EXPECT_TRUE(folder.Entries().empty());
}

TEST(AtomicFileTest, CallbackThatWritesNothingIsAnError) {
  TemporaryFolder folder;
  EXPECT_THROW(WriteFileAtomically(folder / "empty.txt", [](const std::filesystem::path&) {}),
               UserError);
  EXPECT_TRUE(folder.Entries().empty());
}

TEST(AtomicFileTest, DestinationThatIsAFolderIsAUserErrorNamingIt) {
  TemporaryFolder folder;
  std::filesystem::create_directories(folder / "taken/inner");
  const std::string message =
      testing_util::UserErrorMessage([&] { WriteTextFileAtomically(folder / "taken", "x"); });
  EXPECT_THAT(message, StartsWith((folder / "taken").string() + ": cannot write ("));
  EXPECT_THAT(folder.Entries(), ElementsAre("taken"));
}

TEST(AtomicFileTest, ParentThatIsAFileIsAUserError) {
  TemporaryFolder folder;
  WriteTextFileAtomically(folder / "file", "x");
  EXPECT_THROW(WriteTextFileAtomically(folder / "file/child.txt", "y"), UserError);
}

}  // namespace
}  // namespace colav

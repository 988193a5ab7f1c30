#include "src/logging.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using testing_util::ReadFile;
using testing_util::TemporaryFolder;

class LoggingTest : public ::testing::Test {
 protected:
  // Back to a terminal-only logger, so no test leaves a file open for the next.
  ~LoggingTest() override { InitLogging("test", "", false); }
};

TEST_F(LoggingTest, WritesToTerminalAndFile) {
  TemporaryFolder folder;
  const auto log = folder / "logs/prog.log";
  ::testing::internal::CaptureStderr();
  InitLogging("prog", log, false);
  spdlog::info("epoch {} done", 3);
  spdlog::debug("hidden detail");
  const std::string terminal = ::testing::internal::GetCapturedStderr();
  EXPECT_THAT(terminal, HasSubstr("epoch 3 done"));
  EXPECT_THAT(ReadFile(log), HasSubstr("[info] epoch 3 done"));
  EXPECT_THAT(ReadFile(log), Not(HasSubstr("hidden detail")));
}

TEST_F(LoggingTest, VerboseShowsDebugAndFileIsAppended) {
  TemporaryFolder folder;
  const auto log = folder / "prog.log";
  testing_util::WriteFile(log, "earlier run\n");
  ::testing::internal::CaptureStderr();
  InitLogging("prog", log, true);
  spdlog::debug("detail");
  ::testing::internal::GetCapturedStderr();
  EXPECT_THAT(ReadFile(log), HasSubstr("earlier run\n"));
  EXPECT_THAT(ReadFile(log), HasSubstr("[debug] detail"));
}

TEST_F(LoggingTest, UnwritableLogFileIsAUserError) {
  TemporaryFolder folder;
  std::filesystem::create_directories(folder / "a_folder");
  EXPECT_THAT(
      testing_util::UserErrorMessage([&] { InitLogging("prog", folder / "a_folder", false); }),
      HasSubstr((folder / "a_folder").string() + ": cannot open log file"));
}

}  // namespace
}  // namespace colav

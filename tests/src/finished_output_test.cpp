#include "src/finished_output.h"

#include <gtest/gtest.h>

#include "src/error.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;

TEST(FinishedOutputTest, RefusesWhenEveryOutputExistsUnlessOverwriting) {
  TemporaryFolder folder;
  testing_util::WriteFile(folder / "a.png", "x");
  testing_util::WriteFile(folder / "b.png", "x");
  EXPECT_EQ(testing_util::UserErrorMessage([&] {
              RefuseToReplaceFinishedOutput({folder / "a.png", folder / "b.png"}, "--out", false);
            }),
            "--out " + (folder / "a.png").string() +
                ": already written by a finished run; replace it with --overwrite");
  EXPECT_NO_THROW(
      RefuseToReplaceFinishedOutput({folder / "a.png", folder / "b.png"}, "--out", true));
}

TEST(FinishedOutputTest, AcceptsAnInterruptedRunThatWroteOnlySomeOutputs) {
  TemporaryFolder folder;
  testing_util::WriteFile(folder / "a.png", "x");
  EXPECT_NO_THROW(
      RefuseToReplaceFinishedOutput({folder / "a.png", folder / "b.png"}, "--out", false));
  EXPECT_NO_THROW(RefuseToReplaceFinishedOutput({folder / "c.h5"}, "--out", false));
}

}  // namespace
}  // namespace colav

#include "eval/study/study_wall_clock.h"

#include <gtest/gtest.h>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::WriteFile;

TEST(StudyWallClockTest, RanksRunningAtOnceCountOnce) {
  EXPECT_DOUBLE_EQ(CoveredSeconds({}), 0.0);
  EXPECT_DOUBLE_EQ(CoveredSeconds({{10, 20}}), 10.0);
  // Two ranks of one launch overlap; a later rerun adds its own span.
  EXPECT_DOUBLE_EQ(CoveredSeconds({{100, 160}, {10, 20}, {12, 25}, {14, 18}}), 75.0);
  EXPECT_DOUBLE_EQ(CoveredSeconds({{0, 5}, {5, 8}}), 8.0);
}

TEST(StudyWallClockTest, RecordedSpansAndAnOlderRunnersDurations) {
  const TemporaryFolder folder;
  EXPECT_DOUBLE_EQ(StudyWallClock(folder.path()), 0.0);
  RecordWallClockSpan(folder.path(), {1000.0, 1030.0});
  RecordWallClockSpan(folder.path(), {1010.0, 1040.0});
  EXPECT_DOUBLE_EQ(StudyWallClock(folder.path()), 40.0);
  WriteFile(folder / "wall_clock.tsv", "12.5\n7.5\n");
  EXPECT_DOUBLE_EQ(StudyWallClock(folder.path()), 60.0);
}

}  // namespace
}  // namespace colav

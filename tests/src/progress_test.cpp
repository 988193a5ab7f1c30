#include "src/progress.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace colav {
namespace {

using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::Not;

TEST(ProgressFormatTest, Durations) {
  EXPECT_EQ(FormatDuration(0), "00:00");
  EXPECT_EQ(FormatDuration(65.9), "01:05");
  EXPECT_EQ(FormatDuration(3599), "59:59");
  EXPECT_EQ(FormatDuration(3661), "1:01:01");
  EXPECT_EQ(FormatDuration(100 * 3600), "100:00:00");
  EXPECT_EQ(FormatDuration(-1), "--:--");
  EXPECT_EQ(FormatDuration(std::numeric_limits<double>::infinity()), "--:--");
  EXPECT_EQ(FormatDuration(std::numeric_limits<double>::quiet_NaN()), "--:--");
}

TEST(ProgressFormatTest, Rates) {
  EXPECT_EQ(FormatRate(0, "steps"), "0.00 steps/s");
  EXPECT_EQ(FormatRate(0.5, "steps"), "0.50 steps/s");
  EXPECT_EQ(FormatRate(12.34, "scans"), "12.3 scans/s");
  EXPECT_EQ(FormatRate(812.4, "steps"), "812 steps/s");
  EXPECT_EQ(FormatRate(9999, "steps"), "9999 steps/s");
  EXPECT_EQ(FormatRate(12345, "steps"), "12.3k steps/s");
  EXPECT_EQ(FormatRate(4.5e6, "steps"), "4.5M steps/s");
}

ProgressState Quarter() {
  ProgressState state;
  state.label = "train";
  state.done = 50;
  state.total = 200;
  state.unit = "steps";
  state.elapsed_s = 10;
  state.rate = 5;
  state.metrics = {{"loss", "0.1"}, {"reward", "-3"}};
  return state;
}

TEST(ProgressFormatTest, LineWithBar) {
  EXPECT_EQ(FormatProgressLine(Quarter(), 20),
            "train [#####---------------] 50/200 steps 25.0%  5.00 steps/s  elapsed 00:10  "
            "ETA 00:30  loss=0.1  reward=-3");
}

TEST(ProgressFormatTest, PlainLineHasNoBar) {
  EXPECT_EQ(
      FormatProgressLine(Quarter(), 0),
      "train 50/200 steps 25.0%  5.00 steps/s  elapsed 00:10  ETA 00:30  loss=0.1  reward=-3");
}

TEST(ProgressFormatTest, UnknownTotalHasNoBarPercentageOrEta) {
  ProgressState state = Quarter();
  state.total = 0;
  state.metrics.clear();
  EXPECT_EQ(FormatProgressLine(state, 20), "train 50 steps  5.00 steps/s  elapsed 00:10");
}

TEST(ProgressFormatTest, NoRateYetMeansUnknownEta) {
  ProgressState state = Quarter();
  state.rate = 0;
  EXPECT_THAT(FormatProgressLine(state, 0), HasSubstr("ETA --:--"));
}

TEST(ProgressFormatTest, OvershootIsClampedInTheBar) {
  ProgressState state = Quarter();
  state.done = 250;
  EXPECT_THAT(FormatProgressLine(state, 4), HasSubstr("[####] 250/200 steps 100.0%"));
}

// A ProgressBar on a fake clock, writing to a string.
class ProgressBarTest : public ::testing::Test {
 protected:
  ProgressOptions Options(bool interactive) {
    ProgressOptions options;
    options.interactive = interactive;
    options.plain_interval_s = 10;
    options.clock = [this] { return now_s_; };
    options.out = &out_;
    return options;
  }

  double now_s_ = 100.0;
  std::ostringstream out_;
};

TEST_F(ProgressBarTest, PlainModePrintsALineEveryIntervalAndAtFinish) {
  ProgressBar bar("generate", 1000, "scans", Options(false));
  for (int second = 1; second <= 25; ++second) {
    now_s_ = 100.0 + second;
    bar.Update(second * 20, {{"kept", std::to_string(second)}});
  }
  bar.Finish();
  bar.Finish();  // idempotent
  EXPECT_EQ(out_.str(),
            "generate 200/1000 scans 20.0%  20.0 scans/s  elapsed 00:10  ETA 00:40  kept=10\n"
            "generate 400/1000 scans 40.0%  20.0 scans/s  elapsed 00:20  ETA 00:30  kept=20\n"
            "generate 500/1000 scans 50.0%  20.0 scans/s  elapsed 00:25  ETA 00:25  kept=25\n");
}

TEST_F(ProgressBarTest, InteractiveModeRedrawsAtMostTenTimesASecond) {
  ProgressBar bar("train", 1000, "steps", Options(true));
  for (int i = 1; i <= 1000; ++i) {
    now_s_ = 100.0 + i * 0.001;  // 1000 updates in one second
    bar.Update(i);
  }
  const std::string drawn = out_.str();
  const auto redraws = std::count(drawn.begin(), drawn.end(), '\r');
  EXPECT_GE(redraws, 9);
  EXPECT_LE(redraws, 11);
  EXPECT_THAT(out_.str(), Not(HasSubstr("\n")));
  bar.Finish();
  EXPECT_THAT(out_.str(), EndsWith("\033[K\n"));
  EXPECT_THAT(out_.str(), HasSubstr("1000/1000 steps 100.0%"));
}

TEST_F(ProgressBarTest, KeepsTheLastMetricsWhenAnUpdateHasNone) {
  ProgressBar bar("train", 10, "steps", Options(false));
  now_s_ += 1;
  bar.Update(1, {{"loss", "0.5"}});
  bar.Update(2);
  bar.Finish();
  EXPECT_THAT(out_.str(),
              HasSubstr("2/10 steps 20.0%  2.00 steps/s  elapsed 00:01  ETA 00:04  loss=0.5"));
}

TEST_F(ProgressBarTest, ResumedRunsCountOnlyNewWorkInTheRate) {
  ProgressOptions options = Options(false);
  options.initial_done = 500;
  ProgressBar bar("train", 1000, "steps", options);
  now_s_ += 10;
  bar.Update(600);
  bar.Finish();
  EXPECT_THAT(out_.str(),
              HasSubstr("600/1000 steps 60.0%  10.0 steps/s  elapsed 00:10  ETA 00:40"));
}

TEST_F(ProgressBarTest, DestructorFinishesTheLine) {
  { ProgressBar bar("train", 10, "steps", Options(true)); }
  EXPECT_THAT(out_.str(), EndsWith("\n"));
}

}  // namespace
}  // namespace colav

// The replay page's embedded data: it reads back exactly, it matches the `simulate` trace of the
// episode, and a long episode among many obstacles stays small.
#include "eval/replay/replay_page.h"

#include <gtest/gtest.h>

#include <iostream>
#include <random>
#include <sstream>

#include "env/range_finder.h"
#include "tests/eval/replay/replay_episode.h"

namespace colav {
namespace {

std::vector<double> CsvNumbers(const std::string& row) {
  std::vector<double> numbers;
  std::istringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');) numbers.push_back(std::stod(cell));
  return numbers;
}

void ExpectSameStep(const ReplayStep& a, const ReplayStep& b) {
  EXPECT_EQ(a.pose.x, b.pose.x);
  EXPECT_EQ(a.pose.y, b.pose.y);
  EXPECT_EQ(a.pose.heading, b.pose.heading);
  EXPECT_EQ(a.surge, b.surge);
  EXPECT_EQ(a.cross_track_error, b.cross_track_error);
  EXPECT_EQ(a.look_ahead_point.x, b.look_ahead_point.x);
  EXPECT_EQ(a.action, b.action);
  EXPECT_EQ(a.reward, b.reward);
  EXPECT_EQ(a.collision, b.collision);
  EXPECT_EQ(a.closeness, b.closeness);
}

TEST(ReplayPage, DataReadsBackExactly) {
  const Replay replay = testing_util::HeadOnEpisode().replay;
  const Replay read = ReplayOfPage(ReplayPage(replay));
  EXPECT_EQ(read.scene.name, "head-on");
  ASSERT_EQ(read.scene.path.size(), replay.scene.path.size());
  EXPECT_EQ(read.scene.path.back().y, replay.scene.path.back().y);
  ASSERT_EQ(read.scene.vessel_poses.size(), replay.scene.vessel_poses.size());
  EXPECT_EQ(read.scene.vessel_poses.back()[0].y, replay.scene.vessel_poses.back()[0].y);
  EXPECT_EQ(read.scene.vessel_widths, replay.scene.vessel_widths);
  ASSERT_EQ(read.runs.size(), 1u);
  EXPECT_EQ(read.runs[0].label, "straight");
  ASSERT_EQ(read.runs[0].steps.size(), replay.runs[0].steps.size());
  for (std::size_t k = 0; k < replay.runs[0].steps.size(); ++k) {
    ExpectSameStep(read.runs[0].steps[k], replay.runs[0].steps[k]);
  }
}

// Trace columns: step,x,y,psi,u,v,r,cte,heading_error,look_ahead_heading_error,progress,reward,
// terminated,truncated,collision,range_0..range_179.
TEST(ReplayPage, DataMatchesTheTrace) {
  const testing_util::RecordedEpisode episode = testing_util::HeadOnEpisode();
  const Replay read = ReplayOfPage(ReplayPage(episode.replay));
  const std::vector<ReplayStep>& steps = read.runs.at(0).steps;
  ASSERT_EQ(steps.size(), episode.trace_rows.size());
  ASSERT_GT(steps.size(), 100u);
  EXPECT_TRUE(steps.back().collision) << "the head-on episode ends in a collision";
  const double half_byte = RangeFinder::kRange / 255.0 / 2.0 + 1e-4;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const std::vector<double> row = CsvNumbers(episode.trace_rows[k]);
    const ReplayStep& step = steps[k];
    const double recorded[] = {step.pose.x,
                               step.pose.y,
                               step.pose.heading,
                               step.surge,
                               step.sway,
                               step.yaw_rate,
                               step.cross_track_error,
                               step.heading_error,
                               step.look_ahead_heading_error,
                               step.progress,
                               step.reward};
    for (int c = 0; c < 11; ++c) {
      EXPECT_NEAR(recorded[c], row[1 + c], 1e-6 * (1.0 + std::abs(row[1 + c])))
          << "step " << k << " column " << 1 + c;
    }
    EXPECT_EQ(step.collision, row[14] == 1.0) << "step " << k;
    for (int i = 0; i < kNumRays; ++i) {
      EXPECT_NEAR(RangeOfClosenessByte(step.closeness[i]), row[15 + i], half_byte)
          << "step " << k << " ray " << i;
    }
  }
}

// The bound: a 2,000-step episode of one model among 28 obstacles (the training
// worlds' 11 circles and 17 vessels) in under 2 MB.
TEST(ReplayPage, LongEpisodeAmongManyObstaclesStaysUnderTwoMegabytes) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> number(-1000.0f, 1000.0f);
  Replay replay;
  replay.scene.name = "training world";
  for (int i = 0; i < 1500; ++i) replay.scene.path.push_back({number(random), number(random)});
  for (int i = 0; i < 11; ++i) replay.scene.circles.push_back({number(random), number(random), 30});
  replay.scene.vessel_widths.assign(17, 10.0f);
  ReplayRun run{"model", {}};
  for (int k = 0; k <= 2000; ++k) {
    std::vector<ReplayPose> poses;
    for (int j = 0; j < 17; ++j) poses.push_back({number(random), number(random), number(random)});
    replay.scene.vessel_poses.push_back(poses);
    ReplayStep step;
    step.pose = {number(random), number(random), number(random)};
    step.reward = number(random);
    for (auto& c : step.closeness) c = static_cast<std::uint8_t>(random());
    run.steps.push_back(step);
  }
  replay.runs.push_back(run);
  const std::size_t bytes = ReplayPage(replay).size();
  EXPECT_LT(bytes, 2'000'000u);
  std::cout << "replay page of 2,001 steps among 28 obstacles: " << bytes << " bytes\n";
}

TEST(ReplayPage, TextThatIsNotAReplayIsRefused) {
  EXPECT_THROW(ReplayOfPage("<html></html>"), std::invalid_argument);
  EXPECT_THROW(ReplayOfPage("<script type=\"application/json\" id=\"replay-data\">{}</script>"),
               std::invalid_argument);
}

TEST(ReplayPage, LabelsCannotEndTheDataScript) {
  Replay replay = testing_util::HeadOnEpisode().replay;
  replay.runs[0].label = "</script><b>";
  const std::string page = ReplayPage(replay);
  EXPECT_EQ(page.find("</script><b>"), std::string::npos);
  EXPECT_EQ(ReplayOfPage(page).runs[0].label, "</script><b>");
}

}  // namespace
}  // namespace colav

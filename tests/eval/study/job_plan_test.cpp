#include "eval/study/job_plan.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::WriteFile;

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

StudyJob Job(const std::string& id, const std::string& program, double estimated_s) {
  StudyJob job;
  job.id = id;
  job.program = program;
  job.estimated_s = estimated_s;
  return job;
}

// A job is complete by its marker (a summary only when it says it finished), resumable by its
// checkpoint, else to run; only the work not yet done counts toward the estimate.
TEST(JobPlanTest, ListsEachJobsStateProgramWorkAndDependencies) {
  const TemporaryFolder folder;
  StudyJob dataset = Job("data", "generate_dataset", 30.0);
  dataset.complete_marker = folder / "data.h5";
  WriteFile(dataset.complete_marker, "h5");
  StudyJob stopped = Job("ppo/a/seed_0", "train_ppo", 100.0);
  stopped.complete_marker = folder / "a_summary.json";
  stopped.resume_marker = folder / "a_state.pt";
  stopped.dependencies = {0};
  WriteFile(stopped.complete_marker, R"({"finished": false})");
  WriteFile(stopped.resume_marker, "state");
  StudyJob evaluation = Job("eval/study", "evaluate", 50.0);
  evaluation.complete_marker = folder / "eval_summary.json";
  evaluation.resume_marker = folder / "never.pt";
  evaluation.dependencies = {0, 1};
  StudyJob figure = Job("figures/a", "plot_training", 2.0);
  figure.dependencies = {0, 1, 2, 1, 0};  // lists the first three
  const std::vector<std::string> lines =
      Lines(DescribeJobPlan({dataset, stopped, evaluation, figure}));
  ASSERT_EQ(lines.size(), 6U);  // a header, four jobs, the totals
  EXPECT_EQ(lines[1].rfind("complete", 0), 0U) << lines[1];
  EXPECT_NE(lines[1].find(" 30  data "), std::string::npos) << lines[1];
  EXPECT_EQ(lines[1].substr(lines[1].size() - 2), " -");  // waits for nothing
  EXPECT_EQ(lines[2].rfind("resumable", 0), 0U) << lines[2];
  EXPECT_NE(lines[2].find("train_ppo"), std::string::npos);
  EXPECT_EQ(lines[2].substr(lines[2].size() - 5), " data");
  EXPECT_EQ(lines[3].rfind("to run", 0), 0U) << lines[3];
  EXPECT_EQ(lines[3].substr(lines[3].size() - 19), " data, ppo/a/seed_0");
  const std::string listed = " data, ppo/a/seed_0, eval/study and 2 more";
  EXPECT_EQ(lines[4].substr(lines[4].size() - listed.size()), listed);
  EXPECT_EQ(lines[5], "4 jobs: 1 complete, 3 to run or resume (152 work-s estimated)");
}

}  // namespace
}  // namespace colav

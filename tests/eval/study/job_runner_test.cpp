#include "eval/study/job_runner.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/src/test_util.h"

namespace colav {
namespace {

// A job program that, unless told "incomplete", writes its complete marker, then asks its runner
// (the test process) to stop, and waits to be stopped: the runner's SIGTERM ends it by signal.
constexpr const char* kStoppedJobProgram = R"(#!/bin/sh
[ "$2" = incomplete ] || touch "$1"
kill -TERM "$PPID"
exec sleep 30
)";

JobRunSummary RunOneStoppedJob(const testing_util::TemporaryFolder& folder, bool complete) {
  const std::filesystem::path program = folder / "stopped_job.sh";
  std::ofstream(program) << kStoppedJobProgram;
  std::filesystem::permissions(program, std::filesystem::perms::owner_all);
  StudyJob job;
  job.id = "ppo/baseline/seed_0";
  job.program = program.filename().string();
  job.complete_marker = folder / "complete";
  job.args = {job.complete_marker.string(), complete ? "complete" : "incomplete"};
  JobRunnerOptions options;
  options.jobs = 1;
  options.program_dir = folder.path();
  options.log_dir = folder / "logs";
  options.claim_dir = folder / "claims";
  return RunJobs({job}, options);
}

// A stop that reaches a job as its program ends, its outputs already complete (mpirun ending a
// rank just then), counts the job as finished: the next run would skip it as complete, and no run
// would ever say it finished. Without its outputs, the job is one to resume.
TEST(JobRunnerTest, AStoppedJobHasFinishedExactlyWhenItsOutputsAreComplete) {
  for (const bool complete : {true, false}) {
    const testing_util::TemporaryFolder folder;
    const JobRunSummary summary = RunOneStoppedJob(folder, complete);
    EXPECT_TRUE(summary.stopped) << complete;
    EXPECT_EQ(summary.finished, complete ? 1 : 0);
    EXPECT_EQ(summary.failed, 0) << complete;
    EXPECT_EQ(summary.completed_study, complete);
  }
}

}  // namespace
}  // namespace colav

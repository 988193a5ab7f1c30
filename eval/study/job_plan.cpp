#include "eval/study/job_plan.h"

#include <fmt/format.h>

#include <filesystem>

#include "eval/study/job_runner.h"

namespace colav {
namespace {

enum class PlannedState { kComplete, kResumable, kToRun };

// Resumable: an interrupted run left the checkpoint it continues from.
PlannedState StateOf(const StudyJob& job) {
  if (JobComplete(job)) return PlannedState::kComplete;
  if (!job.resume_marker.empty() && std::filesystem::exists(job.resume_marker)) {
    return PlannedState::kResumable;
  }
  return PlannedState::kToRun;
}

const char* NameOf(PlannedState state) {
  switch (state) {
    case PlannedState::kComplete:
      return "complete";
    case PlannedState::kResumable:
      return "resumable";
    case PlannedState::kToRun:
      return "to run";
  }
  return "";
}

// The ids of the jobs `job` waits for, comma-separated, the first kMaxListed and a count of the
// others ("-" for none): an evaluation waits for every run.
std::string Dependencies(const StudyJob& job, const std::vector<StudyJob>& jobs) {
  constexpr std::size_t kMaxListed = 3;
  if (job.dependencies.empty()) return "-";
  std::vector<std::string> ids;
  for (const std::size_t dependency : job.dependencies) {
    if (ids.size() == kMaxListed) break;
    ids.push_back(jobs[dependency].id);
  }
  std::string listed = fmt::format("{}", fmt::join(ids, ", "));
  if (job.dependencies.size() > kMaxListed) {
    listed += fmt::format(" and {} more", job.dependencies.size() - kMaxListed);
  }
  return listed;
}

}  // namespace

std::string DescribeJobPlan(const std::vector<StudyJob>& jobs) {
  std::string plan =
      fmt::format("{:<10} {:>9}  {:<48} {:<16} {}\n", "state", "work-s", "job", "program", "after");
  int complete = 0;
  double pending_s = 0.0;
  for (const StudyJob& job : jobs) {
    const PlannedState state = StateOf(job);
    if (state == PlannedState::kComplete) {
      ++complete;
    } else {
      pending_s += job.estimated_s;
    }
    plan += fmt::format("{:<10} {:>9.0f}  {:<48} {:<16} {}\n", NameOf(state), job.estimated_s,
                        job.id, job.program, Dependencies(job, jobs));
  }
  plan += fmt::format("{} jobs: {} complete, {} to run or resume ({:.0f} work-s estimated)\n",
                      jobs.size(), complete, jobs.size() - static_cast<std::size_t>(complete),
                      pending_s);
  return plan;
}

}  // namespace colav

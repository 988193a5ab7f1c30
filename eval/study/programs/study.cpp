// study: runs a study file's whole experiment (interfaces.md, section "study"): the dataset, the
// VAEs, every PPO configuration times its training seeds, the evaluations, then OUT/REPORT.md and
// OUT/summary.json. Up to --jobs programs run at once; complete jobs are skipped and interrupted
// ones continued, so rerunning the same command after a stop or a failure finishes the study.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "eval/study/job_graph.h"
#include "eval/study/job_runner.h"
#include "eval/study/study_report.h"
#include "eval/study/study_spec.h"
#include "src/atomic_file.h"
#include "src/cli.h"
#include "src/error.h"
#include "src/progress.h"
#include "src/threads/thread_pool.h"

namespace colav {
namespace {

// Exit statuses besides 0 (done) and 2 (bad input).
constexpr int kJobsFailedStatus = 1;
constexpr int kStoppedStatus = 130;  // SIGINT/SIGTERM: rerun the same command to continue

// Adds this invocation's wall-clock to OUT/wall_clock.tsv (when it ran jobs) and returns the
// study's total over every invocation, so a resumed study reports its whole cost.
double TotalWallClock(const std::filesystem::path& folder, double wall_s, bool ran_jobs) {
  const std::filesystem::path file = folder / "wall_clock.tsv";
  std::string lines;
  if (std::ifstream in(file); in) lines.assign(std::istreambuf_iterator<char>(in), {});
  if (ran_jobs) {
    lines += Fixed(wall_s, 1) + "\n";
    WriteTextFileAtomically(file, lines);
  }
  double total = 0.0;
  std::istringstream entries(lines);
  for (double entry = 0.0; entries >> entry;) total += entry;
  return total;
}

int Study(int argc, char** argv) {
  CLI::App app{
      "Runs a study: the dataset, the VAEs, each PPO configuration times its training seeds and\n"
      "the evaluations of STUDY.yaml (see studies/), up to --jobs programs at once, then writes\n"
      "OUT/REPORT.md and OUT/summary.json. Jobs whose outputs exist are skipped, interrupted ones\n"
      "continue from their checkpoints: rerun the same command after a stop or a failure.\n"
      "Each job logs to OUT/logs/. Exit status: 0 done, 1 a job failed (its log is named),\n"
      "2 bad input, 130 stopped by SIGINT/SIGTERM (resumable)."};
  std::string study_file;
  std::string out;
  int jobs = ThreadCountOrAllCores(0);
  int seeds = 0;
  std::vector<std::string> only;
  std::vector<std::string> overrides;
  bool report_only = false;
  app.add_option("study", study_file, "study file (YAML)")->required()->type_name("STUDY.yaml");
  app.add_option("--out", out, "study folder (created; reused to resume)")->required();
  app.add_option("--jobs", jobs, "programs running at once (default: one per core)")
      ->check(CLI::Range(1, 64));
  app.add_option("--seeds", seeds, "training seeds of every PPO configuration (0 .. N-1)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--only", only, "run only these PPO configurations (and what they need)");
  app.add_option("--set", overrides, "KEY=VALUE override of every PPO run (train_ppo's keys)");
  app.add_flag("--report", report_only, "only write the report from the finished evaluations");
  ParseCommandLine(app, argc, argv);

  StudySpec spec = SelectConfigs(LoadStudySpec(study_file), only, seeds);
  // The cores are shared between the jobs: each PPO run steps its worlds on its share (spinning
  // threads beyond the cores would slow every job down); the study file or --set may override.
  const int threads_per_job = std::max(1, ThreadCountOrAllCores(0) / jobs);
  spec.ppo_overrides.insert(spec.ppo_overrides.begin(),
                            "train.env_threads=" + std::to_string(threads_per_job));
  spec.ppo_overrides.insert(spec.ppo_overrides.end(), overrides.begin(), overrides.end());
  const std::filesystem::path folder = std::filesystem::absolute(out);
  const auto start = std::chrono::steady_clock::now();
  JobRunSummary summary;
  if (!report_only) {
    const std::vector<StudyJob> graph = BuildJobGraph(spec, folder);
    CheckJobConfigurations(graph, ProgramFolder());
    summary = RunJobs(graph, {jobs, ProgramFolder(), folder / "logs"});
    std::fprintf(stderr, "study: %d jobs run, %d skipped (complete), %d failed\n", summary.finished,
                 summary.skipped, summary.failed);
  }
  const bool ran_jobs = summary.finished > 0 || summary.failed > 0 || summary.stopped;
  const double wall_s = TotalWallClock(folder, SecondsSince(start), ran_jobs);
  if (summary.stopped) return kStoppedStatus;
  if (summary.failed > 0) return kJobsFailedStatus;
  WriteStudyReport(spec, folder, wall_s);
  std::printf("report: %s\nstudy_wall_s: %.1f\n", (folder / "REPORT.md").c_str(), wall_s);
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) { return colav::RunProgram("study", argc, argv, colav::Study); }

// study: runs a study file's whole experiment (interfaces.md, section "study"): the dataset, the
// VAEs, every PPO configuration times its training seeds, the evaluations, then OUT/REPORT.md and
// OUT/summary.json. Up to --jobs programs run at once; complete jobs are skipped and interrupted
// ones continued, so rerunning the same command after a stop or a failure finishes the study.
// Any number of such runners (ranks of mpirun or srun, tasks of a Slurm array, on any machines
// sharing OUT) can run one study together: they claim its jobs through OUT/claims/
// (job_claims.h), and the one that completes the study's last job writes the report.
#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "eval/study/ensemble_observations.h"
#include "eval/study/job_claims.h"
#include "eval/study/job_graph.h"
#include "eval/study/job_plan.h"
#include "eval/study/job_runner.h"
#include "eval/study/launcher_environment.h"
#include "eval/study/process_identity.h"
#include "eval/study/study_report.h"
#include "eval/study/study_spec.h"
#include "eval/study/study_wall_clock.h"
#include "src/cli.h"

namespace colav {
namespace {

// Exit statuses besides 0 (done) and 2 (bad input).
constexpr int kJobsFailedStatus = 1;
constexpr int kStoppedStatus = 130;  // SIGINT/SIGTERM: rerun the same command to continue

// The rank's place in the log, when the study is shared between ranks.
void SayShard(const StudyShard& shard) {
  if (shard.source == "none") return;
  const ProcessIdentity self = CurrentProcess();
  std::fprintf(stderr, "study: rank %d of %d (from %s), host %s, pid %lld\n", shard.index,
               shard.count, shard.source.c_str(), self.host.c_str(),
               static_cast<long long>(self.pid));
}

// The report is written once per completed study: by the rank whose job completed it, or, when no
// job was left to run, by rank 0 (always on one machine, so a rerun prints it again; among ranks
// only if nobody wrote it yet) or by --report.
bool WritesReport(const JobRunSummary& summary, const StudyShard& shard, JobClaims& claims) {
  const bool nothing_to_run = summary.finished == 0 && summary.by_others == 0;
  if (nothing_to_run && shard.index == 0 && shard.count == 1) return true;
  // Among ranks, only the first to claim this completion's report writes it, even if it is still
  // being written (a writer that died before finishing leaves it to `study --report`).
  return (summary.completed_study || (nothing_to_run && shard.index == 0)) &&
         claims.ClaimReportWriting();
}

int Study(int argc, char** argv) {
  CLI::App app{
      "Runs a study: the dataset, the VAEs, each PPO configuration times its training seeds, the\n"
      "ensembles of its runs, the students distilled from them, the students fine-tuned by PPO\n"
      "and the evaluations of STUDY.yaml (see studies/), up to --jobs programs at once, then\n"
      "writes OUT/REPORT.md and OUT/summary.json. Jobs whose outputs\n"
      "exist are skipped, interrupted ones continue from their checkpoints: rerun the same\n"
      "command after a stop or a failure. Finished runs whose recorded settings differ from\n"
      "what STUDY.yaml now asks for are refused before any work, naming the setting.\n"
      "Each job logs to OUT/logs/. Several ranks (mpirun, a Slurm array, or --shard on each\n"
      "machine) can share one study in one folder: they claim its jobs through OUT/claims/.\n"
      "Exit status: 0 done, 1 a job failed (its log is named), 2 bad input, 130 stopped by\n"
      "SIGINT/SIGTERM (resumable)."};
  std::string study_file;
  std::string out;
  const EnvironmentLookup environment = ProcessEnvironment();
  const int cores = CoresOfThisRank(environment);
  int jobs = cores;
  int seeds = 0;
  std::optional<std::string> shard_flag;
  int claim_timeout_s = 300;
  std::vector<std::string> only;
  std::vector<std::string> overrides;
  bool report_only = false;
  bool plan_only = false;
  app.add_option("study", study_file, "study file (YAML)")->required()->type_name("STUDY.yaml");
  app.add_option("--out", out, "study folder (created; reused to resume)")->required();
  app.add_option("--jobs", jobs, "programs running at once (default: one per core of this rank)")
      ->check(CLI::Range(1, 64));
  app.add_option("--seeds", seeds,
                 "training seeds of every PPO configuration (0 .. N-1); an ensemble kind without "
                 "a count in the file follows them, one with a count keeps it (at most what they "
                 "give)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--only", only,
                 "run only these models (PPO configurations, ensembles, students, fine-tunes), "
                 "what is built from them alone, and what they need")
      ->type_name("NAME");
  app.add_option("--set", overrides, "KEY=VALUE override of every PPO run (train_ppo's keys)");
  app.add_flag("--report", report_only, "only write the report from the finished evaluations");
  app.add_flag("--plan", plan_only,
               "print the jobs this command would run (each one's state, program, estimated work "
               "and what it waits for) and exit: nothing is created, run or checked")
      ->excludes("--report");
  app.add_option("--shard", shard_flag,
                 "this rank's share I/N of a study run by N ranks (default: from mpirun's or "
                 "Slurm's environment): it starts on the I-th ready job, then claims any")
      ->type_name("I/N");
  app.add_option("--claim-timeout", claim_timeout_s,
                 "seconds after which a job claim of another host that is not refreshed is taken "
                 "over (its rank is taken as dead)")
      ->check(CLI::Range(10, 7 * 24 * 3600));
  ParseCommandLine(app, argc, argv);
  const StudyShard shard = ResolveShard(shard_flag, environment);

  StudySpec spec = SelectModels(LoadStudySpec(study_file), only, seeds);
  // The cores are shared between the jobs: each PPO run steps its worlds on its share (spinning
  // threads beyond the cores would slow every job down); the study file or --set may override.
  const int threads_per_job = std::max(1, cores / jobs);
  spec.ppo_overrides.insert(spec.ppo_overrides.begin(),
                            "train.env_threads=" + std::to_string(threads_per_job));
  spec.ppo_overrides.insert(spec.ppo_overrides.end(), overrides.begin(), overrides.end());
  const std::filesystem::path folder = std::filesystem::absolute(out);
  if (plan_only) {
    std::fputs(DescribeJobPlan(BuildJobGraph(spec, folder)).c_str(), stdout);
    return 0;
  }
  const double start_s = UnixSeconds();
  JobRunSummary summary;
  JobClaims claims(folder / "claims", CurrentProcess(), std::chrono::seconds(claim_timeout_s));
  if (!report_only) {
    SayShard(shard);
    const std::vector<StudyJob> graph = BuildJobGraph(spec, folder);
    if (!AllJobsComplete(graph)) claims.ForgetReportWriting();
    CheckEnsembleObservationSettings(spec, study_file, folder,
                                     CheckJobConfigurations(graph, ProgramFolder()));
    summary = RunJobs(graph, {jobs, ProgramFolder(), folder / "logs", folder / "claims",
                              std::chrono::seconds(claim_timeout_s), shard.index});
    std::fprintf(stderr,
                 "study: %d jobs run, %d skipped (complete), %d by other ranks, %d failed\n",
                 summary.finished, summary.skipped, summary.by_others, summary.failed);
    if (summary.finished > 0 || summary.failed > 0 || summary.stopped) {
      RecordWallClockSpan(folder, {start_s, UnixSeconds()});
    }
  }
  if (summary.stopped) return kStoppedStatus;
  if (summary.failed > 0) return kJobsFailedStatus;
  if (!report_only && !WritesReport(summary, shard, claims)) {
    std::fprintf(stderr, "study: complete; the rank that completed it writes the report\n");
    return 0;
  }
  const double wall_s = StudyWallClock(folder);
  WriteStudyReport(spec, folder, wall_s);
  std::printf("report: %s\nstudy_wall_s: %.1f\n", (folder / "REPORT.md").c_str(), wall_s);
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) { return colav::RunProgram("study", argc, argv, colav::Study); }

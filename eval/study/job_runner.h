// Runs the jobs of a study as child processes, up to N at a time, in dependency order: complete
// jobs are skipped, interrupted ones continued from their checkpoints, and one progress line
// covers the whole study. Each job's output goes to LOG_DIR/<job id with '/' as '_'>.log.
//
// A job runs only under its claim (job_claims.h), so several runners (ranks, on one machine or
// many sharing the study folder) can work on one study at once: each takes the ready jobs nobody
// holds, waits for jobs held by others (a job's dependencies too), takes over the jobs of ranks
// that died, and treats a failure another rank recorded as its own. A single runner is a study
// of one rank.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <vector>

#include "eval/study/job_graph.h"

namespace colav {

struct JobRunnerOptions {
  int jobs = 2;                       ///< child processes at once
  std::filesystem::path program_dir;  ///< where generate_dataset, train_ppo, ... are
  std::filesystem::path log_dir;      ///< one log per job
  std::filesystem::path claim_dir;    ///< the jobs' claims, shared by every rank
  /// A claim of another host whose heartbeat is older is stale (its holder is taken as dead).
  std::chrono::seconds claim_timeout{300};
  /// Where this rank starts among the ready jobs (its shard index), so that ranks started
  /// together begin on different jobs.
  int start_offset = 0;
};

struct JobRunSummary {
  int skipped = 0;       ///< complete before this run
  int finished = 0;      ///< run to completion now
  int failed = 0;        ///< ended without their outputs, or blocked by a failed dependency
  int by_others = 0;     ///< completed by other ranks during this run
  bool stopped = false;  ///< SIGINT/SIGTERM: running jobs were stopped to resume later
  /// A job of this run was the last of the study to complete (this rank writes the report).
  bool completed_study = false;
};

/// Asks each job's program to resolve its configuration (--print-config) before anything runs,
/// so that a bad key or value in the study fails at once: a UserError naming the job and the
/// program's own one-line message. A finished job whose run recorded its settings (config.yaml
/// beside its complete marker) is checked too, and one whose recorded settings differ from those
/// the study now asks for is a UserError naming the setting (recorded_settings.h). Returns each
/// checked job's resolved configuration (YAML) by job id.
std::map<std::string, std::string> CheckJobConfigurations(const std::vector<StudyJob>& jobs,
                                                          const std::filesystem::path& program_dir);

/// Runs `jobs` (dependencies before dependants) until every job is complete or failed, here or on
/// another rank. SIGINT or SIGTERM stops launching jobs and asks the running ones to stop cleanly
/// (they checkpoint), then returns with `stopped`. A job's program gets SIGTERM when its runner
/// dies, so that it checkpoints and its claim can be taken over.
JobRunSummary RunJobs(const std::vector<StudyJob>& jobs, const JobRunnerOptions& options);

/// Whether the job's outputs are complete: its complete marker exists and, for a summary that says
/// whether its run finished (train_ppo writes one when stopped too), says so; an evaluation's
/// lists exactly its expected models.
bool JobComplete(const StudyJob& job);

/// Whether the outputs of every job are complete (a finished study, whoever ran it).
bool AllJobsComplete(const std::vector<StudyJob>& jobs);

/// The folder of the running program (/proc/self/exe), where the other programs are built.
std::filesystem::path ProgramFolder();

}  // namespace colav

// Runs the jobs of a study as child processes, up to N at a time, in dependency order: complete
// jobs are skipped, interrupted ones continued from their checkpoints, and one progress line
// covers the whole study. Each job's output goes to LOG_DIR/<job id with '/' as '_'>.log.
#pragma once

#include <filesystem>
#include <vector>

#include "eval/study/job_graph.h"

namespace colav {

struct JobRunnerOptions {
  int jobs = 2;                       ///< child processes at once
  std::filesystem::path program_dir;  ///< where generate_dataset, train_ppo, ... are
  std::filesystem::path log_dir;      ///< one log per job
};

struct JobRunSummary {
  int skipped = 0;       ///< complete before this run
  int finished = 0;      ///< run to completion now
  int failed = 0;        ///< ended without their outputs, or blocked by a failed dependency
  bool stopped = false;  ///< SIGINT/SIGTERM: running jobs were stopped to resume later
};

/// Asks each job's program to resolve its configuration (--print-config) before anything runs,
/// so that a bad key or value in the study fails at once: a UserError naming the job and the
/// program's own one-line message.
void CheckJobConfigurations(const std::vector<StudyJob>& jobs,
                            const std::filesystem::path& program_dir);

/// Runs `jobs` (dependencies before dependants). SIGINT or SIGTERM stops launching jobs and asks
/// the running ones to stop cleanly (they checkpoint), then returns with `stopped`.
JobRunSummary RunJobs(const std::vector<StudyJob>& jobs, const JobRunnerOptions& options);

/// The folder of the running program (/proc/self/exe), where the other programs are built.
std::filesystem::path ProgramFolder();

}  // namespace colav

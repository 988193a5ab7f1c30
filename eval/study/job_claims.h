// Claims on a study's jobs through the shared output folder, so that ranks on several machines
// (mpirun, Slurm) share one study with nothing between them but that folder: a rank runs a job
// only while it holds the job's claim, no job runs twice at once, and a rank that dies loses only
// the jobs it was running, which another rank then takes over.
//
// The claims of job J are files CLAIMS/J/<generation>.claim, each created whole and exclusively
// (written to a private file, then link()ed to its name, which fails if the name exists, also on
// NFS). The highest generation is the claim in force. Its holder refreshes the file's time (the
// heartbeat) while it runs the job and removes the claim files when the job ends. A claim whose
// holder died is stale: on the holder's own host, when neither the holder nor the program it ran
// for the job still runs (pid and start time); on another host, when its heartbeat is older than
// the timeout. A rank takes a stale claim over by creating the next generation: of several ranks
// trying at once, exactly one succeeds. A holder that finds a higher generation than its own has
// been taken over (its heartbeat stalled) and must stop its job.
//
// A job that failed leaves CLAIMS/J/failed, so that the ranks running at the time block its
// dependants as a one-machine run does; a rank started later retries it.
//
// CLAIMS/report.written marks that the study's last completion has its report writer.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "eval/study/process_identity.h"

namespace colav {

using WallTime = std::chrono::system_clock::time_point;

/// One claim file's content.
struct JobClaim {
  std::string job;  ///< the job's id, e.g. "ppo/baseline/seed_0"
  std::int64_t generation = 1;
  ProcessIdentity holder;  ///< the study rank
  ProcessIdentity worker;  ///< the program it runs for the job (pid 0 before it starts)
  std::string started;     ///< UTC time of the claim, for people
};

/// "host:pid" of a claim's holder, for messages.
std::string HolderName(const JobClaim& claim);

struct ClaimAttempt {
  bool claimed = false;
  /// The claim in force before the attempt: the stale one taken over, or the live one that holds
  /// the job (nullopt: there was none, or it changed during the attempt).
  std::optional<JobClaim> previous;
};

class JobClaims {
 public:
  /// The claims under `folder`, made by `self`; claims of other hosts are stale once their
  /// heartbeat is older than `timeout`.
  JobClaims(std::filesystem::path folder, ProcessIdentity self, std::chrono::seconds timeout);

  /// Claims `job` when nobody holds it or its holder died (`now` judges heartbeats).
  ClaimAttempt TryClaim(const std::string& job, WallTime now);

  /// Records in the held claim of `job` the program that runs it, so that the claim stays live
  /// on this host until that program ends, even if this rank dies first.
  void RecordWorker(const std::string& job, const ProcessIdentity& worker);

  /// Refreshes the heartbeat of every held claim. Returns the jobs whose claims another rank took
  /// over: they are no longer held and their programs must stop.
  std::vector<std::string> Heartbeat();

  /// Gives the claim of `job` up (its job ended or stopped); a claim taken over is left alone.
  void Release(const std::string& job);

  /// Records that `job` failed (`reason`: its log and last line), for every rank to see.
  void RecordFailure(const std::string& job, const std::string& reason);

  /// The reason `job` failed when that was recorded at or after `since`.
  std::optional<std::string> FailureSince(const std::string& job, WallTime since) const;

  /// Removes the failure record of `job` (it is retried).
  void ClearFailure(const std::string& job);

  /// Of the ranks that complete the study at the same moment, exactly one gets true: it writes
  /// the report (CLAIMS/report.written, created exclusively, names it).
  bool ClaimReportWriting();
  /// The study is incomplete again (a rank starts on it): its next completion needs a report.
  void ForgetReportWriting();

 private:
  std::filesystem::path JobFolder(const std::string& job) const;
  bool Stale(const JobClaim& claim, WallTime heartbeat, WallTime now) const;
  bool StillHeld(const JobClaim& claim) const;

  std::filesystem::path folder_;
  ProcessIdentity self_;
  std::chrono::seconds timeout_;
  std::map<std::string, JobClaim> held_;
};

}  // namespace colav

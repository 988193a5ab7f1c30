// Who holds a job's claim (job_claims.h), precisely enough to tell whether it still runs: the host
// and its boot (a reboot ends every process), the pid and the process's start time (pids are
// reused).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>

namespace colav {

struct ProcessIdentity {
  std::string host;     ///< host name, for people reading a claim
  std::string boot_id;  ///< /proc/sys/kernel/random/boot_id: this host since its last boot
  std::int64_t pid = 0;
  std::uint64_t start_ticks = 0;  ///< /proc/<pid>/stat start time: tells a reused pid apart

  bool operator==(const ProcessIdentity& other) const {
    return boot_id == other.boot_id && pid == other.pid && start_ticks == other.start_ticks;
  }
};

/// The running process.
ProcessIdentity CurrentProcess();

/// Process `pid` of this host (start_ticks 0 when it does not exist).
ProcessIdentity ProcessOnThisHost(pid_t pid);

/// Whether `process` ran on this host since its last boot, so that its liveness can be checked.
bool OnThisHost(const ProcessIdentity& process);

/// Whether `process`, of this host, still runs (a zombie no longer does).
bool StillRunning(const ProcessIdentity& process);

}  // namespace colav

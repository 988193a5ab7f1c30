// The lock that keeps two processes from writing one run folder: flock(2) on DIR/.lock, which
// also records the holder (program, pid, host) for the refusal the second process prints. The
// kernel releases the lock when the holder ends, however it ends (SIGKILL included), so a left-over
// .lock file never blocks a later run.
#pragma once

#include <filesystem>
#include <string>

namespace colav {

class RunLock {
 public:
  /// Locks the existing folder `dir` for `program` until destroyed; a folder another process holds
  /// is a UserError naming the folder and the holder.
  RunLock(const std::filesystem::path& dir, const std::string& program);
  ~RunLock();
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;

  /// DIR/.lock.
  static std::filesystem::path PathIn(const std::filesystem::path& dir);

 private:
  int descriptor_ = -1;
};

}  // namespace colav

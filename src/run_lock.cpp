#include "src/run_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "src/error.h"

namespace colav {
namespace {

std::string HostName() {
  char name[256] = {};
  return gethostname(name, sizeof(name) - 1) == 0 ? name : "unknown host";
}

// What the holder wrote into the lock file ("train_ppo, pid 123 on host h").
std::string Holder(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string holder;
  std::getline(in, holder);
  return holder.empty() ? "another process" : holder;
}

}  // namespace

std::filesystem::path RunLock::PathIn(const std::filesystem::path& dir) { return dir / ".lock"; }

RunLock::RunLock(const std::filesystem::path& dir, const std::string& program) {
  const std::filesystem::path path = PathIn(dir);
  descriptor_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (descriptor_ < 0) {
    throw UserError(dir.string() + ": cannot create the run folder's lock " + path.string() + " (" +
                    std::strerror(errno) + ")");
  }
  if (flock(descriptor_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    close(descriptor_);
    if (error != EWOULDBLOCK) {
      throw UserError(path.string() + ": cannot lock (" + std::strerror(error) + ")");
    }
    throw UserError(dir.string() + ": run folder in use by " + Holder(path) +
                    " (one process writes a run folder at a time)");
  }
  const std::string holder =
      program + ", pid " + std::to_string(getpid()) + " on host " + HostName() + "\n";
  // The record is for the message only: the flock, not the text, is the lock.
  if (ftruncate(descriptor_, 0) != 0 ||
      write(descriptor_, holder.data(), holder.size()) != static_cast<ssize_t>(holder.size())) {
    close(descriptor_);
    throw UserError(path.string() + ": cannot write (" + std::strerror(errno) + ")");
  }
}

RunLock::~RunLock() { close(descriptor_); }

}  // namespace colav

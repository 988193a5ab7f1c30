#include "src/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include "src/error.h"

namespace colav {
namespace {

std::filesystem::path TemporaryPathFor(const std::filesystem::path& path) {
  static std::atomic<std::uint64_t> counter{0};
  const std::string name = "." + path.filename().string() + ".tmp-" + std::to_string(getpid()) +
                           "-" + std::to_string(counter++);
  return path.parent_path() / name;
}

// Flushes a file's (or a folder's) data to disk, so that after a power cut the renamed file has
// its content. False, with errno set, on failure.
bool Fsync(const std::filesystem::path& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool synced = fsync(fd) == 0;
  const int fsync_errno = errno;
  close(fd);
  errno = fsync_errno;
  return synced;
}

[[noreturn]] void ThrowCannotWrite(const std::filesystem::path& path, const std::string& reason) {
  throw UserError(path.string() + ": cannot write (" + reason + ")");
}

}  // namespace

void WriteFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write) {
  const std::filesystem::path folder = path.parent_path();
  std::error_code error;
  if (!folder.empty()) std::filesystem::create_directories(folder, error);
  if (error) {
    throw UserError(folder.string() + ": cannot create folder (" + error.message() + ")");
  }
  const std::filesystem::path temporary = TemporaryPathFor(path);
  try {
    write(temporary);
    if (!Fsync(temporary)) ThrowCannotWrite(path, std::strerror(errno));
    std::filesystem::rename(temporary, path, error);
    if (error) ThrowCannotWrite(path, error.message());
  } catch (...) {
    std::filesystem::remove(temporary, error);
    throw;
  }
  // Persists the rename; best effort, since the file is complete either way.
  Fsync(folder.empty() ? "." : folder);
}

void WriteTextFileAtomically(const std::filesystem::path& path, const std::string& content) {
  WriteFileAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream file(temporary, std::ios::binary);
    file << content;
    file.close();
    if (!file) ThrowCannotWrite(path, std::strerror(errno));
  });
}

}  // namespace colav

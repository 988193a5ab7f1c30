#include "src/output_path.h"

#include <unistd.h>

#include <system_error>

#include "src/error.h"

namespace colav {
namespace {

[[noreturn]] void Refuse(const std::string& flag, const std::filesystem::path& path,
                         const std::string& reason) {
  throw UserError(flag + (path.empty() ? "" : " " + path.string()) + ": " + reason);
}

// `path` itself when it exists, else its nearest existing ancestor ("." for a relative path).
std::filesystem::path NearestExisting(std::filesystem::path path) {
  std::error_code error;
  while (!path.empty() && !std::filesystem::exists(path, error)) path = path.parent_path();
  return path.empty() ? std::filesystem::path(".") : path;
}

// The nearest existing ancestor of `folder`, which will hold `path` or be it, must be a folder we
// may write into.
void RequireCreatableIn(const std::filesystem::path& folder, const std::filesystem::path& path,
                        const std::string& flag) {
  const std::filesystem::path existing = NearestExisting(folder);
  if (!std::filesystem::is_directory(existing)) {
    Refuse(flag, path, existing.string() + " is not a folder");
  }
  if (access(existing.c_str(), W_OK | X_OK) != 0) {
    Refuse(flag, path, "cannot write into " + existing.string());
  }
}

}  // namespace

void RequireWritableFile(const std::filesystem::path& path, const std::string& flag) {
  if (path.empty()) Refuse(flag, path, "empty path");
  if (std::filesystem::is_directory(path)) Refuse(flag, path, "is a folder, not a file");
  if (!path.has_filename()) Refuse(flag, path, "names a folder, not a file");
  RequireCreatableIn(path.parent_path().empty() ? "." : path.parent_path(), path, flag);
}

void RequireWritableFolder(const std::filesystem::path& path, const std::string& flag) {
  if (path.empty()) Refuse(flag, path, "empty path");
  if (std::filesystem::exists(path) && !std::filesystem::is_directory(path)) {
    Refuse(flag, path, "exists and is not a folder");
  }
  RequireCreatableIn(path, path, flag);
}

}  // namespace colav

// Atomic file writing: a reader (or a crash, or Ctrl-C) never sees a half-written output file.
//
// Every writer of the project goes through WriteFileAtomically: the content is written to a
// temporary file in the destination folder, flushed to disk, then renamed over the destination,
// which POSIX makes atomic within one file system.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace colav {

/// Creates the parent folders of `path`, calls `write` with a temporary path in the same folder
/// (".<name>.tmp-<pid>-<n>") for it to create and fill with any writer (ofstream, HDF5,
/// torch::save), then fsyncs it and renames it to `path`. If `write` throws, the temporary file is
/// removed, `path` keeps its old content and the exception propagates. Failing file-system calls
/// are a colav::UserError naming `path`.
void WriteFileAtomically(
    const std::filesystem::path& path,
    const std::function<void(const std::filesystem::path& temporary_path)>& write);

/// Writes `content` to `path` atomically.
void WriteTextFileAtomically(const std::filesystem::path& path, const std::string& content);

}  // namespace colav

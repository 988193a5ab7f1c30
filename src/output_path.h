// Checks of output paths before any work: a program that would fail to write its result only
// after minutes of work checks the path first, and reports it in one line naming the flag.
#pragma once

#include <filesystem>
#include <string>

namespace colav {

/// A file can be written at `path` (given with `flag`, e.g. "--out"): it is not empty and not a
/// folder, and its nearest existing ancestor is a folder this process may write into. A
/// colav::UserError naming the flag and the path otherwise. Creates nothing.
void RequireWritableFile(const std::filesystem::path& path, const std::string& flag);

/// A folder can be written at `path`: it is a folder, or can be created, and may be written into.
void RequireWritableFolder(const std::filesystem::path& path, const std::string& flag);

}  // namespace colav

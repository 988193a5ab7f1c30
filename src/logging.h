// Logging set-up: every program logs through spdlog's default logger (spdlog::info(...)), to the
// terminal and, when it has a run folder, to a log file there.
#pragma once

#include <filesystem>
#include <string>

namespace colav {

/// Replaces spdlog's default logger with one named `program` that writes to stderr (coloured
/// when stderr is a terminal) and, unless `log_file` is empty, appends to `log_file` (creating its
/// folder). Level debug when `verbose`, else info. An unwritable log file is a colav::UserError.
void InitLogging(const std::string& program, const std::filesystem::path& log_file, bool verbose);

}  // namespace colav

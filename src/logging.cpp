#include "src/logging.h"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <memory>
#include <vector>

#include "src/error.h"

namespace colav {

void InitLogging(const std::string& program, const std::filesystem::path& log_file, bool verbose) {
  auto terminal = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  // On a terminal, a log line first erases a ProgressBar line being redrawn in place (the bar
  // comes back at its next update) instead of being glued to its end.
  const std::string erase_line = isatty(STDERR_FILENO) != 0 ? "\r\033[K" : "";
  terminal->set_pattern(erase_line + "[%H:%M:%S] [%^%l%$] %v");
  std::vector<spdlog::sink_ptr> sinks = {terminal};
  if (!log_file.empty()) {
    try {
      auto file = std::make_shared<spdlog::sinks::basic_file_sink_mt>(log_file.string());
      file->set_pattern("[%Y-%m-%d %H:%M:%S.%e] [%l] %v");
      sinks.push_back(file);
    } catch (const spdlog::spdlog_ex& e) {
      throw UserError(log_file.string() + ": cannot open log file (" + e.what() + ")");
    }
  }
  auto logger = std::make_shared<spdlog::logger>(program, sinks.begin(), sinks.end());
  logger->set_level(verbose ? spdlog::level::debug : spdlog::level::info);
  // Log lines are few (per epoch, per checkpoint); flushing each keeps the file complete when a
  // run is killed.
  logger->flush_on(spdlog::level::debug);
  spdlog::set_default_logger(logger);
}

}  // namespace colav

#include "src/run_folder.h"

#include <system_error>
#include <utility>

#include "src/atomic_file.h"
#include "src/cli.h"
#include "src/error.h"

namespace colav {

RunFolder::RunFolder(std::filesystem::path path, std::string program)
    : path_(std::move(path)), program_(std::move(program)) {}

RunFolder RunFolder::Create(const std::filesystem::path& dir, const std::string& program) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) {
    const std::string reason = error ? error.message() : "not a folder";
    throw UserError(dir.string() + ": cannot create run folder (" + reason + ")");
  }
  return RunFolder(dir, program.empty() ? ProgramName() : program);
}

std::filesystem::path RunFolder::DefaultPath(const std::string& name) {
  return std::filesystem::path("runs") / name;
}

void RunFolder::WriteResolvedConfig(const Config& config) const {
  WriteTextFileAtomically(path_ / "config.yaml", config.ToYaml());
}

std::filesystem::path RunFolder::LogPath() const { return path_ / (program_ + ".log"); }

}  // namespace colav

// The run-folder convention: every training or evaluation run writes its outputs, its resolved
// configuration (config.yaml) and its log (<program>.log) into one folder, by default
// runs/<name>/ when the program is given no --out.
#pragma once

#include <filesystem>
#include <string>

#include "src/config.h"

namespace colav {

class RunFolder {
 public:
  /// Creates `dir` (and its parents) if needed; an existing folder is reused (resumed runs).
  /// `program` names the log file; by default the one RunProgram runs.
  static RunFolder Create(const std::filesystem::path& dir, const std::string& program = "");
  /// runs/<name>, relative to the working folder.
  static std::filesystem::path DefaultPath(const std::string& name);

  const std::filesystem::path& path() const { return path_; }
  /// Writes the configuration as dir/config.yaml (atomically), so the run can be reproduced.
  void WriteResolvedConfig(const Config& config) const;
  /// dir/<program>.log.
  std::filesystem::path LogPath() const;

 private:
  RunFolder(std::filesystem::path path, std::string program);

  std::filesystem::path path_;
  std::string program_;
};

}  // namespace colav

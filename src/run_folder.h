// The run-folder convention: every training or evaluation run writes its outputs, its resolved
// configuration (config.yaml) and its log (<program>.log) into one folder, by default
// runs/<name>/ when the program is given no --out. One process writes a folder at a time
// (RunLock); a new run never replaces a finished or resumable one without --overwrite, and a
// resumed run keeps the configuration it was started with.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "src/config.h"
#include "src/run_lock.h"

namespace colav {

/// A setting whose value differs between two configurations.
struct DifferingSetting {
  std::string key;
  std::string value;           ///< in the configuration at hand
  std::string recorded_value;  ///< in the recorded one; "(none)" when it lacks the key
};

/// The first key (in name order) whose value in `config` differs from `recorded`'s, `free_keys`
/// (settings that do not change results) aside; none when they agree.
std::optional<DifferingSetting> FirstDifferingSetting(const Config& config, const Config& recorded,
                                                      const std::vector<std::string>& free_keys);

class RunFolder {
 public:
  /// Creates `dir` (and its parents) if needed and locks it for this process's lifetime (a folder
  /// another process holds is a UserError naming the holder); an existing folder is reused.
  /// `program` names the log file and the lock's holder; by default the one RunProgram runs.
  static RunFolder Create(const std::filesystem::path& dir, const std::string& program = "");
  /// runs/<name>, relative to the working folder.
  static std::filesystem::path DefaultPath(const std::string& name);

  const std::filesystem::path& path() const { return path_; }
  /// Prepares the folder for a new run. One that holds a run (any of `markers`, the files a
  /// finished or resumable run leaves) is refused with a UserError naming it and `hint` (what to
  /// do instead), unless `overwrite`. Then `outputs` (paths relative to the folder: the run's files
  /// and folders, markers included) are removed, so no file of an earlier run mixes with the new.
  void StartNewRun(const std::vector<std::string>& markers, const std::vector<std::string>& outputs,
                   bool overwrite, const std::string& hint) const;
  /// For a run that continues: `config` must equal the folder's config.yaml (read with `schema`,
  /// config's), except for `free_keys` (settings that do not change results, such as thread
  /// counts). A UserError names the first key that differs.
  void RequireConfigUnchanged(const Config& config, const ConfigSchema& schema,
                              const std::vector<std::string>& free_keys = {}) const;
  /// The same check against `recorded`, the configuration the run was trained with as kept in
  /// `source` (a file, named in the error): a config.yaml edited by hand is refused too.
  void RequireConfigUnchanged(const Config& config, const Config& recorded,
                              const std::string& source,
                              const std::vector<std::string>& free_keys) const;
  /// Writes the configuration as dir/config.yaml (atomically), so the run can be reproduced.
  void WriteResolvedConfig(const Config& config) const;
  /// dir/<program>.log.
  std::filesystem::path LogPath() const;

 private:
  RunFolder(std::filesystem::path path, std::string program);

  std::filesystem::path path_;
  std::string program_;
  std::shared_ptr<const RunLock> lock_;  ///< shared by the copies; released with the last one
};

}  // namespace colav

#include "src/finished_output.h"

#include <algorithm>

#include "src/error.h"

namespace colav {

void RefuseToReplaceFinishedOutput(const std::vector<std::filesystem::path>& outputs,
                                   const std::string& flag, bool overwrite) {
  const auto exists = [](const std::filesystem::path& path) {
    return std::filesystem::exists(path);
  };
  if (overwrite || outputs.empty() || !std::all_of(outputs.begin(), outputs.end(), exists)) return;
  throw UserError(flag + " " + outputs.front().string() +
                  ": already written by a finished run; replace it with --overwrite");
}

}  // namespace colav

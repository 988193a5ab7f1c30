// A finished result is never replaced by accident: a program whose outputs all exist already
// refuses to run again over them unless given --overwrite. Outputs are written atomically, so one
// that exists is complete; a run that wrote only some of them was interrupted and may redo them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace colav {

/// A UserError naming `flag` and the first output when every one of `outputs` exists and
/// `overwrite` is false (checked before any work).
void RefuseToReplaceFinishedOutput(const std::vector<std::filesystem::path>& outputs,
                                   const std::string& flag, bool overwrite);

}  // namespace colav

// The running program's build: the GNU build ID the linker writes into the executable (a hash of
// its linked contents), so results recorded by one build can be told from another's (an
// evaluation's episodes, eval/reused_episodes.h). The project's libraries are linked statically,
// so any change to the code a program runs changes its ID.
#pragma once

#include <string>

namespace colav {

/// The running executable's GNU build ID in hex ("9afcc65f..."); empty when it has none (linked
/// without --build-id).
std::string ProgramBuildId();

}  // namespace colav

// Where the test suites find the project's files (configs/, studies/) and its build folder.
// Defined in the one translation unit CMake generates from tests/project_paths.cpp.in, so no
// other test object depends on where the checkout lives and ccache reuses them across clones.
#pragma once

namespace colav::testing_util {

extern const char* const kSourceDir;  ///< the checkout's root (PROJECT_SOURCE_DIR)
extern const char* const kBinaryDir;  ///< the build folder (CMAKE_BINARY_DIR)

}  // namespace colav::testing_util

// The running program's build ID, against what binutils' readelf reads from the same file.
#include "src/build_id.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>

namespace colav {
namespace {

// readelf's "Build ID: <hex>" of this test's own executable; empty when readelf finds none.
std::string ReadelfBuildId() {
  const std::string command = "readelf -n /proc/" + std::to_string(getpid()) + "/exe 2>/dev/null";
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string output;
  std::array<char, 256> chunk{};
  while (pipe && fgets(chunk.data(), chunk.size(), pipe.get()) != nullptr) output += chunk.data();
  const std::string label = "Build ID: ";
  const std::size_t at = output.find(label);
  if (at == std::string::npos) return {};
  const std::size_t start = at + label.size();
  return output.substr(start, output.find('\n', start) - start);
}

TEST(ProgramBuildIdTest, IsTheOneTheLinkerWrote) {
  const std::string id = ProgramBuildId();
  EXPECT_EQ(id.size(), 40U) << id;  // SHA-1, the linker's default
  EXPECT_EQ(id, ReadelfBuildId());
}

}  // namespace
}  // namespace colav

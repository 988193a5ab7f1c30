#include "eval/policy_fingerprint.h"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <fstream>

#include "eval/policy.h"
#include "src/error.h"
#include "src/fnv1a.h"

namespace colav {
namespace {

constexpr std::size_t kReadChunkBytes = 1 << 16;

// Continues the FNV-1a hash `hash` over the bytes of `file`.
std::uint64_t HashFileBytes(const std::filesystem::path& file, std::uint64_t hash) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw UserError(file.string() + ": cannot be read");
  std::array<char, kReadChunkBytes> chunk{};
  while (in.read(chunk.data(), chunk.size()) || in.gcount() > 0) {
    hash = Fnv1a({chunk.data(), static_cast<std::size_t>(in.gcount())}, hash);
  }
  return hash;
}

}  // namespace

std::string PolicyFingerprint(const std::filesystem::path& policy) {
  std::uint64_t hash = HashFileBytes(policy, kFnv1aOffsetBasis);
  const std::filesystem::path sidecar = SidecarPath(policy);
  if (std::filesystem::is_regular_file(sidecar)) hash = HashFileBytes(sidecar, hash);
  return fmt::format("fnv1a64:{:016x}", hash);
}

}  // namespace colav

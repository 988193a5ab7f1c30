#include "eval/policy_fingerprint.h"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <fstream>

#include "eval/policy.h"
#include "src/error.h"

namespace colav {
namespace {

constexpr std::uint64_t kFnvOffsetBasis = 0xCBF29CE484222325ULL;
constexpr std::uint64_t kFnvPrime = 0x100000001B3ULL;
constexpr std::size_t kReadChunkBytes = 1 << 16;

// Continues the FNV-1a hash `hash` over the bytes of `file`.
std::uint64_t HashFileBytes(const std::filesystem::path& file, std::uint64_t hash) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw UserError(file.string() + ": cannot be read");
  std::array<char, kReadChunkBytes> chunk{};
  while (in.read(chunk.data(), chunk.size()) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      hash ^= static_cast<unsigned char>(chunk[static_cast<std::size_t>(i)]);
      hash *= kFnvPrime;
    }
  }
  return hash;
}

}  // namespace

std::string PolicyFingerprint(const std::filesystem::path& policy) {
  std::uint64_t hash = HashFileBytes(policy, kFnvOffsetBasis);
  const std::filesystem::path sidecar = SidecarPath(policy);
  if (std::filesystem::is_regular_file(sidecar)) hash = HashFileBytes(sidecar, hash);
  return fmt::format("fnv1a64:{:016x}", hash);
}

}  // namespace colav

// FNV-1a, 64 bits: a fast non-cryptographic hash of bytes, for names mixed into seeds
// (src/seeding.h) and for telling whether a file changed (eval/policy_fingerprint.h).
#pragma once

#include <cstdint>
#include <string_view>

namespace colav {

inline constexpr std::uint64_t kFnv1aOffsetBasis = 0xCBF29CE484222325ULL;

/// The FNV-1a hash of `bytes`, continuing from `hash` (the offset basis for a fresh hash), so data
/// read in chunks hashes as if read at once.
constexpr std::uint64_t Fnv1a(std::string_view bytes, std::uint64_t hash = kFnv1aOffsetBasis) {
  constexpr std::uint64_t kPrime = 0x100000001B3ULL;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= kPrime;
  }
  return hash;
}

}  // namespace colav

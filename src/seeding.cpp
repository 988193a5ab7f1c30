#include "src/seeding.h"

#include "src/fnv1a.h"

namespace colav {
namespace {

// SplitMix64 finaliser: a bijective mixer with good avalanche, the standard way to turn
// correlated integers (0, 1, 2, ...) into unrelated seeds.
std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27U)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31U);
}

}  // namespace

std::uint64_t DeriveSeed(std::uint64_t master_seed, std::string_view component,
                         std::uint64_t index) {
  return SplitMix64(SplitMix64(SplitMix64(master_seed) ^ Fnv1a(component)) + index);
}

Rng MakeRng(std::uint64_t master_seed, std::string_view component, std::uint64_t index) {
  return Rng(DeriveSeed(master_seed, component, index));
}

}  // namespace colav

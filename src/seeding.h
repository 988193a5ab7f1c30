// Seeding: one master seed in, independent reproducible random streams out.
//
// Every random component (an environment, a dataset generator, a network initialiser) asks for
// its own stream by name and index, so adding a component never shifts another one's numbers.
#pragma once

#include <cstdint>
#include <random>
#include <string_view>

namespace colav {

/// The project's random engine: 64-bit Mersenne Twister (same numbers on every platform).
using Rng = std::mt19937_64;

/// Seed of stream (component, index) derived from a master seed by SplitMix64 mixing of the
/// master seed, a FNV-1a hash of the component name and the index.
std::uint64_t DeriveSeed(std::uint64_t master_seed, std::string_view component,
                         std::uint64_t index = 0);

/// A random engine seeded with DeriveSeed(master_seed, component, index).
Rng MakeRng(std::uint64_t master_seed, std::string_view component, std::uint64_t index = 0);

}  // namespace colav

// Samplers on top of colav::Rng with the same numbers on every platform.
//
// The standard library's distributions are implementation-defined (libstdc++ and libc++ give
// different numbers for the same engine), so the few samplers the project needs are written out.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "src/seeding.h"

namespace colav {

/// Uniform on [0, 1) with 53 random bits.
inline double Uniform01(Rng& rng) { return static_cast<double>(rng() >> 11U) * 0x1.0p-53; }

/// Uniform on [low, high).
inline double Uniform(Rng& rng, double low, double high) {
  return low + (high - low) * Uniform01(rng);
}

/// Uniform integer in [0, n) (n > 0), by rejection so every value is equally likely.
std::uint64_t UniformIndex(Rng& rng, std::uint64_t n);

/// Normal(mean, sd) by the Box-Muller transform (one value per call, no cached state).
double Normal(Rng& rng, double mean, double sd);

/// Poisson(lambda): Knuth's product method for lambda < 30, otherwise the PTRS transformed
/// rejection method of Hoermann (1993), the one numpy uses.
std::int64_t Poisson(Rng& rng, double lambda);

/// Index k drawn with probability weights[k] / sum(weights) (inverse CDF, one uniform).
std::size_t Discrete(Rng& rng, const std::vector<double>& weights);

}  // namespace colav

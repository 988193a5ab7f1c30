#include "src/random.h"

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "src/log_gamma.h"

namespace colav {

std::uint64_t UniformIndex(Rng& rng, std::uint64_t n) {
  if (n == 0) throw std::invalid_argument("UniformIndex: n must be positive");
  const std::uint64_t limit = Rng::max() - (Rng::max() % n);
  std::uint64_t x = rng();
  while (x >= limit) x = rng();
  return x % n;
}

double Normal(Rng& rng, double mean, double sd) {
  constexpr double kTwoPi = 6.283185307179586476925286766559;
  const double u1 = 1.0 - Uniform01(rng);  // (0, 1]: log is finite
  const double u2 = Uniform01(rng);
  return mean + sd * std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
}

std::int64_t Poisson(Rng& rng, double lambda) {
  if (lambda <= 0.0) return 0;
  if (lambda < 30.0) {
    const double limit = std::exp(-lambda);
    std::int64_t k = 0;
    double product = Uniform01(rng);
    while (product > limit) {
      ++k;
      product *= Uniform01(rng);
    }
    return k;
  }
  // PTRS (Hoermann 1993), as in numpy's legacy random_poisson_ptrs.
  const double slam = std::sqrt(lambda);
  const double loglam = std::log(lambda);
  const double b = 0.931 + 2.53 * slam;
  const double a = -0.059 + 0.02483 * b;
  const double invalpha = 1.1239 + 1.1328 / (b - 3.4);
  const double vr = 0.9277 - 3.6224 / (b - 2);
  while (true) {
    const double u = Uniform01(rng) - 0.5;
    const double v = Uniform01(rng);
    const double us = 0.5 - std::fabs(u);
    const double k = std::floor((2 * a / us + b) * u + lambda + 0.43);
    if (us >= 0.07 && v <= vr) return static_cast<std::int64_t>(k);
    if (k < 0 || (us < 0.013 && v > us)) continue;
    if (std::log(v) + std::log(invalpha) - std::log(a / (us * us) + b) <=
        -lambda + k * loglam - LogGamma(k + 1)) {
      return static_cast<std::int64_t>(k);
    }
  }
}

std::size_t Discrete(Rng& rng, const std::vector<double>& weights) {
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  const double target = Uniform01(rng) * total;
  double cumulative = 0.0;
  for (std::size_t k = 0; k < weights.size(); ++k) {
    cumulative += weights[k];
    if (target < cumulative) return k;
  }
  return weights.size() - 1;
}

}  // namespace colav

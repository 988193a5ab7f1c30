#include "src/rate_interval.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "src/random.h"
#include "src/seeding.h"

namespace colav {

Interval WilsonInterval(std::int64_t successes, std::int64_t trials, double z) {
  if (trials <= 0 || successes < 0 || successes > trials) {
    throw std::invalid_argument("WilsonInterval: " + std::to_string(successes) + " of " +
                                std::to_string(trials));
  }
  const double n = static_cast<double>(trials);
  const double p = static_cast<double>(successes) / n;
  const double z2 = z * z;
  const double centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
  const double half = z / (1.0 + z2 / n) * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n));
  // Mathematically 0 of n ends at 0 and n of n at 1; set them so rounding cannot move them.
  return {successes == 0 ? 0.0 : std::max(0.0, centre - half),
          successes == trials ? 1.0 : std::min(1.0, centre + half)};
}

double Quantile(std::vector<double> values, double q) {
  if (values.empty() || !(q >= 0.0 && q <= 1.0)) {
    throw std::invalid_argument("Quantile: empty values or q outside [0, 1]");
  }
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return values[below] + fraction * (values[above] - values[below]);
}

Interval PercentileBootstrapMean(const std::vector<double>& values, std::uint64_t seed,
                                 int resamples, double level) {
  if (values.empty() || resamples < 1 || !(level > 0.0 && level < 1.0)) {
    throw std::invalid_argument("PercentileBootstrapMean: empty values or bad settings");
  }
  Rng rng = MakeRng(seed, "percentile-bootstrap");
  std::vector<double> means(static_cast<std::size_t>(resamples));
  for (double& mean : means) {
    double sum = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) sum += values[UniformIndex(rng, values.size())];
    mean = sum / static_cast<double>(values.size());
  }
  return {Quantile(means, (1.0 - level) / 2.0), Quantile(means, (1.0 + level) / 2.0)};
}

}  // namespace colav

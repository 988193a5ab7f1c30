// Confidence intervals that stay inside the range of what they estimate: the Wilson score
// interval of a rate (collisions, goals reached) and the percentile bootstrap of a bounded mean
// (progress). The Student-t interval of src/statistics.h can leave [0, 1] for rates near 0 or 1
// ("collisions 16.7 % [-26.2, 59.5]" on 6 episodes); these cannot.
#pragma once

#include <cstdint>
#include <vector>

namespace colav {

/// A two-sided interval estimate.
struct Interval {
  double low = 0.0;
  double high = 0.0;
};

/// z of the two-sided 95 % normal interval.
inline constexpr double kNormal95 = 1.959963984540054;

/// Wilson score interval of the rate successes / trials (Wilson 1927), inside [0, 1] for every
/// count: 0 of n gives [0, z^2 / (n + z^2)]. trials > 0 and 0 <= successes <= trials
/// (std::invalid_argument otherwise).
Interval WilsonInterval(std::int64_t successes, std::int64_t trials, double z = kNormal95);

/// Percentile bootstrap interval of the mean of `values` (not empty): the (1-level)/2 and
/// (1+level)/2 quantiles of the means of `resamples` resamples drawn with replacement by a
/// generator seeded with `seed`. Inside [min, max] of the values. Same seed, same interval.
Interval PercentileBootstrapMean(const std::vector<double>& values, std::uint64_t seed,
                                 int resamples = 2000, double level = 0.95);

/// The q-quantile (0 <= q <= 1) of `values` (not empty) with linear interpolation between order
/// statistics (numpy's default, "linear").
double Quantile(std::vector<double> values, double q);

}  // namespace colav

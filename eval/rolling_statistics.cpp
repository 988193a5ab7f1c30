#include "eval/rolling_statistics.h"

#include <stdexcept>

#include "src/statistics.h"

namespace colav {

std::vector<RollingPoint> RollingMeanSd(const std::vector<double>& values, std::size_t window) {
  if (window == 0) throw std::invalid_argument("RollingMeanSd: window must be positive");
  std::vector<RollingPoint> points;
  points.reserve(values.size());
  // Recomputed per window rather than updated incrementally: a few thousand episodes of 100
  // values, and no drift from subtracting large sums.
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::size_t first = i + 1 >= window ? i + 1 - window : 0;
    const std::vector<double> recent(values.begin() + static_cast<std::ptrdiff_t>(first),
                                     values.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    points.push_back({Mean(recent), SampleStandardDeviation(recent)});
  }
  return points;
}

}  // namespace colav

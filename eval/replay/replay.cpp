#include "eval/replay/replay.h"

#include <algorithm>
#include <cmath>

#include "env/range_finder.h"

namespace colav {

std::uint8_t ClosenessByte(double range) {
  const double closeness = 1.0 - std::clamp(range / RangeFinder::kRange, 0.0, 1.0);
  return static_cast<std::uint8_t>(std::lround(255.0 * closeness));
}

double RangeOfClosenessByte(std::uint8_t closeness) {
  return RangeFinder::kRange * (1.0 - closeness / 255.0);
}

int ReplayLength(const Replay& replay) {
  std::size_t length = 0;
  for (const ReplayRun& run : replay.runs) length = std::max(length, run.steps.size());
  return static_cast<int>(length);
}

}  // namespace colav

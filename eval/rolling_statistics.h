// Rolling mean and standard deviation over the last episodes, as the paper's training curves show
// them (rolling average over 100 episodes with a shaded rolling standard deviation).
#pragma once

#include <cstddef>
#include <vector>

namespace colav {

struct RollingPoint {
  double mean = 0.0;
  double sd = 0.0;  ///< sample standard deviation; 0 while the window holds one value
};

/// Point i summarises values[max(0, i - window + 1) .. i] (window >= 1): early points use the
/// values seen so far.
std::vector<RollingPoint> RollingMeanSd(const std::vector<double>& values, std::size_t window);

}  // namespace colav

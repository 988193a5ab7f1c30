// The constant of the diagonal normal policy's log-density, shared by the rollout (which records
// each action's log-probability) and the loss (which computes it again for the ratio).
#pragma once

#include <cmath>

namespace colav {

/// log sqrt(2 pi): each dimension's share of -log of the normal density's normaliser.
inline const double kLogSqrtTwoPi = 0.5 * std::log(2.0 * M_PI);

}  // namespace colav

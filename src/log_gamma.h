// ln |Gamma(x)|, safe to call from several threads at once.
#pragma once

#include <cmath>

namespace colav {

/// std::lgamma also writes the sign of Gamma(x) to the global `signgam` (POSIX), a data race
/// when worlds are generated on several threads (ThreadSanitizer reports it); lgamma_r returns
/// the sign in a local instead.
inline double LogGamma(double x) {
  int sign = 0;
  return ::lgamma_r(x, &sign);
}

}  // namespace colav

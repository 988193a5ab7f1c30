#include "src/log_gamma.h"

#include <gtest/gtest.h>

#include <cmath>

namespace colav {
namespace {

TEST(LogGammaTest, MatchesHandValues) {
  EXPECT_DOUBLE_EQ(LogGamma(1.0), 0.0);
  EXPECT_NEAR(LogGamma(5.0), std::log(24.0), 1e-14);
  EXPECT_NEAR(LogGamma(0.5), 0.5 * std::log(M_PI), 1e-14);
  EXPECT_NEAR(LogGamma(-0.5), std::log(2.0 * std::sqrt(M_PI)), 1e-14);  // |Gamma(-1/2)|
}

// The reason it exists: the global that std::lgamma writes (the sign of Gamma(-1/2) is -1) is
// left alone, so calls on different threads do not race on it.
TEST(LogGammaTest, LeavesTheGlobalSignAlone) {
  signgam = 7;
  LogGamma(-0.5);
  EXPECT_EQ(signgam, 7);
}

}  // namespace
}  // namespace colav

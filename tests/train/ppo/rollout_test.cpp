// Which episode ends continue their return with gamma * V(final observation).
#include "train/ppo/rollout.h"

#include <gtest/gtest.h>

namespace colav {
namespace {

TEST(BootstrapsFromFinalObservation, OnlyATimeOutThatDidNotAlsoTerminate) {
  // Stable-Baselines3: TimeLimit.truncated = truncated and not terminated.
  EXPECT_TRUE(BootstrapsFromFinalObservation(/*terminated=*/false, /*truncated=*/true, false));
  EXPECT_FALSE(BootstrapsFromFinalObservation(true, true, false));  // collided on the last step
  EXPECT_FALSE(BootstrapsFromFinalObservation(true, false, false));
  EXPECT_FALSE(BootstrapsFromFinalObservation(false, false, false));
}

TEST(BootstrapsFromFinalObservation, NeverWhenTimeOutsAreTerminal) {
  for (const bool terminated : {false, true}) {
    for (const bool truncated : {false, true}) {
      EXPECT_FALSE(BootstrapsFromFinalObservation(terminated, truncated, true));
    }
  }
}

}  // namespace
}  // namespace colav

#include "src/threads/thread_pool.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace colav {
namespace {

TEST(ThreadPool, CoversEveryIndexOnceAndPropagatesErrors) {
  ThreadPool pool(3);
  std::vector<int> hits(100, 0);
  for (int round = 0; round < 50; ++round) pool.ParallelFor(100, [&](int i) { ++hits[i]; });
  for (const int h : hits) EXPECT_EQ(h, 50);
  EXPECT_THROW(pool.ParallelFor(10,
                                [](int i) {
                                  if (i == 7) throw std::runtime_error("x");
                                }),
               std::runtime_error);
}

}  // namespace
}  // namespace colav

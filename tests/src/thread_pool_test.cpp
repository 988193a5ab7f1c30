#include "src/threads/thread_pool.h"

#include <gtest/gtest.h>

#include <atomic>
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

TEST(ThreadPool, WatchingCallerPollsAndSeesEveryIndexOnce) {
  std::vector<std::atomic<int>> hits(1000);
  int polls = 0;
  ParallelFor(
      1000, 3, [&](int i) { ++hits[i]; }, [&] { ++polls; });
  for (const std::atomic<int>& h : hits) EXPECT_EQ(h, 1);
  EXPECT_GE(polls, 1);
  EXPECT_THROW(ParallelFor(
                   10, 2,
                   [](int i) {
                     if (i == 3) throw std::runtime_error("x");
                   },
                   [] {}),
               std::runtime_error);
}

}  // namespace
}  // namespace colav

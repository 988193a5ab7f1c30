#include "src/threads/spin_lock.h"

#include <gtest/gtest.h>

#include <mutex>
#include <thread>
#include <vector>

namespace colav {
namespace {

// Increments that are not atomic, each under the lock: none is lost.
TEST(SpinLock, NoIncrementUnderItIsLost) {
  constexpr int kThreads = 4;
  constexpr int kIncrements = 100'000;
  SpinLock lock;
  long long counter = 0;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < kIncrements; ++i) {
        const std::lock_guard<SpinLock> guard(lock);
        counter = counter + 1;
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(counter, static_cast<long long>(kThreads) * kIncrements);
}

}  // namespace
}  // namespace colav

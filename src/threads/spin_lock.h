// A lock for critical sections of a few dozen instructions, which each thread takes about once
// per step (AsyncEnvironmentPool's task queues). A contended std::mutex puts the waiter to sleep
// in the kernel and its holder wakes it with a system call, together about as costly as a step:
// with one, perf showed the futex wake-ups, and the pool stepped 8 worlds on 2 threads at
// 1.1-1.7x one thread in five runs on a busy machine, against 1.4-1.9x for the synchronous pool
// in the same runs. A thread that finds this lock taken spins instead. Meets BasicLockable, so
// std::lock_guard and std::unique_lock take it.
#pragma once

#include <atomic>
#include <thread>

#include "src/threads/cpu_relax.h"

namespace colav {

class SpinLock {
 public:
  void lock() {
    for (int polls = 0; locked_.exchange(true, std::memory_order_acquire);) {
      while (locked_.load(std::memory_order_relaxed)) {
        if (++polls % kPollsBeforeYield == 0) {
          std::this_thread::yield();
        } else {
          CpuRelax();
        }
      }
    }
  }
  void unlock() { locked_.store(false, std::memory_order_release); }

 private:
  // A waiting thread yields its core after this many polls: the holder may have been preempted
  // on a busy machine.
  static constexpr int kPollsBeforeYield = 256;

  std::atomic<bool> locked_{false};
};

}  // namespace colav

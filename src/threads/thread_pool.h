// A fixed pool of worker threads that runs one parallel loop at a time; the calling thread
// takes part. Built for stepping a few worlds every few microseconds: workers spin briefly
// before sleeping, so back-to-back loops do not pay a futex wake-up each.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace colav {

class ThreadPool {
 public:
  /// num_threads in total, the caller included (1 = no worker threads).
  explicit ThreadPool(int num_threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int num_threads() const { return static_cast<int>(workers_.size()) + 1; }

  /// Calls body(i) for i in [0, count); threads claim the next index as they become free (worlds
  /// that reset cost many steps, so fixed chunks would leave one core idle). Returns when all
  /// calls are done. An exception of body is rethrown in the caller.
  void ParallelFor(int count, const std::function<void(int)>& body);

 private:
  void WorkerLoop();
  void RunClaimedIndices();
  /// Waits until generation_ differs from `seen` or the pool stops; false when stopping.
  bool WaitForWork(std::uint64_t seen);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  const std::function<void(int)>* body_ = nullptr;
  int count_ = 0;
  std::atomic<int> next_index_{0};
  std::atomic<std::uint64_t> generation_{0};
  std::atomic<int> pending_{0};
  std::atomic<bool> stopping_{false};
  std::exception_ptr error_;
};

}  // namespace colav

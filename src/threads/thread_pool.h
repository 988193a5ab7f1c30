// A fixed pool of worker threads that runs one parallel loop at a time. Built for stepping a few
// worlds every few microseconds: workers spin briefly before sleeping, so back-to-back loops do
// not pay a futex wake-up each. Long jobs (one scan, one episode per index) use the free
// ParallelFor, whose caller shows progress while the workers run.
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
  /// that reset cost many steps, so fixed chunks would leave one core idle), the caller included.
  /// Returns when all calls are done. The first exception of body stops handing out indices and
  /// is rethrown in the caller.
  void ParallelFor(int count, const std::function<void(int)>& body);

  /// As above, but only the worker threads (at least one) run body: the caller calls `poll` about
  /// ten times a second while they do, and once after they finish.
  void ParallelFor(int count, const std::function<void(int)>& body,
                   const std::function<void()>& poll);

 private:
  void StartLoop(int count, const std::function<void(int)>& body, bool caller_watches);
  void WorkerLoop();
  void RunClaimedIndices();
  /// Waits until generation_ differs from `seen` or the pool stops; false when stopping.
  bool WaitForWork(std::uint64_t seen);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable workers_done_;  // signalled only when the caller watches
  const std::function<void(int)>* body_ = nullptr;
  int count_ = 0;
  bool caller_watches_ = false;
  std::atomic<int> next_index_{0};
  std::atomic<std::uint64_t> generation_{0};
  std::atomic<int> pending_{0};
  std::atomic<bool> stopping_{false};
  std::exception_ptr error_;
};

/// `configured` if positive, otherwise one thread per core (at least 1).
int ThreadCountOrAllCores(int configured);

/// Calls task(i) for i in [0, count) on `threads` threads (a pool made for the call) while the
/// calling thread calls `poll` about ten times a second (progress display). For independent,
/// individually seeded tasks whose results depend only on their index, so the output does not
/// depend on the thread count.
void ParallelFor(int count, int threads, const std::function<void(int)>& task,
                 const std::function<void()>& poll);

}  // namespace colav

// A fixed pool of worker threads that runs one parallel loop at a time. Built for stepping a few
// worlds every few microseconds: workers spin briefly before sleeping, so back-to-back loops do
// not pay a futex wake-up each, and each thread keeps stepping the same worlds, whose data then
// stays in its core's cache. Long jobs (one scan, one episode per index) use the free
// ParallelFor, whose caller shows progress while the workers run.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
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

  /// The first index of participant p's own share of a loop of `count` indices among
  /// `participants` (ParallelFor's caller is participant 0); its share ends where p + 1's begins.
  static int ShareStart(int count, int participants, int p) {
    return static_cast<int>(static_cast<std::int64_t>(count) * p / participants);
  }

  /// Calls body(i) for i in [0, count) and returns when all calls are done. Each thread (the
  /// caller included) first runs its own contiguous share of the indices, the same one every
  /// loop, then takes indices left in the others' shares (a world that resets costs many steps,
  /// so fixed shares alone would leave a core idle). The first exception of body stops handing
  /// out indices and is rethrown in the caller.
  void ParallelFor(int count, const std::function<void(int)>& body);

  /// As above, but only the worker threads (at least one) run body: the caller calls `poll` about
  /// ten times a second while they do, and once after they finish.
  void ParallelFor(int count, const std::function<void(int)>& body,
                   const std::function<void()>& poll);

  /// Queues `task` for a worker thread to run when no loop needs it: work that must not hold up
  /// the loops, such as preparing a world's next episode while the others step. The loops go on
  /// without the worker meanwhile. Tasks must not throw; without workers they never run, and
  /// tasks still queued when the pool is destroyed are dropped.
  void RunWhenIdle(std::function<void()> task);

 private:
  // One thread's share of a loop's indices. `cursor` packs the loop's tag (its generation's low
  // 32 bits) and the next unclaimed index, so a worker that wakes up late for a finished loop
  // cannot claim an index of the next one.
  struct alignas(64) Share {
    std::atomic<std::uint64_t> cursor{0};
    std::atomic<int> end{0};
  };

  void StartLoop(int count, const std::function<void(int)>& body, bool caller_runs);
  /// Runs indices of loop `generation` as participant `participant` until none is left.
  void Participate(std::uint64_t generation, int participant);
  /// Claims the next index of `share` in loop `tag`; false when the share is used up (or belongs
  /// to another loop).
  static bool Claim(Share& share, std::uint32_t tag, int* index);
  /// Marks `done` indices finished; the participant finishing the loop wakes a watching caller.
  void Finish(int done);
  /// Stops handing out indices of loop `tag` after an exception.
  void Abandon(std::uint32_t tag);
  void WorkerLoop(int worker);
  /// Waits for a loop newer than `seen`, running idle tasks meanwhile: returns its generation, or
  /// `seen` when the pool stops.
  std::uint64_t AwaitLoop(std::uint64_t seen);
  void RunIdleTask();

  std::vector<std::thread> workers_;
  std::unique_ptr<Share[]> shares_;  // one per thread that can run indices
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable loop_done_;  // signalled only when the caller watches
  std::atomic<const std::function<void(int)>*> body_{nullptr};
  std::atomic<int> num_participants_{0};
  std::atomic<bool> caller_watches_{false};
  std::atomic<bool> stopping_{false};
  std::exception_ptr error_;                      // guarded by mutex_
  std::deque<std::function<void()>> idle_tasks_;  // guarded by mutex_
  std::atomic<int> idle_task_count_{0};           // its size, for polling without the mutex
  alignas(64) std::atomic<std::uint64_t> generation_{0};
  alignas(64) std::atomic<int> remaining_{0};  // indices of the current loop not yet finished
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

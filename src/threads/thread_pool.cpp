#include "src/threads/thread_pool.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "src/threads/cpu_relax.h"

namespace colav {
namespace {

using Clock = std::chrono::steady_clock;

// A waiting thread spins on its core for kSpinTime (the gap between two environment steps, a
// policy forward or a Python loop iteration, is 10-30 µs), then yields the core (to the thread
// it waits for, on a busy machine) until kYieldTime, then a worker sleeps.
constexpr auto kSpinTime = std::chrono::microseconds(100);
constexpr auto kYieldTime = std::chrono::milliseconds(2);
constexpr int kPollsPerClockRead = 64;

constexpr std::chrono::milliseconds kPollInterval(100);

// Polls `ready` (spinning, then yielding as above) until it holds or `patience` has passed;
// returns whether it holds.
template <typename Ready>
bool PollUntil(const Ready& ready, Clock::duration patience) {
  const auto start = Clock::now();
  bool spinning = true;
  for (int poll = 1; !ready(); ++poll) {
    if (poll % kPollsPerClockRead == 0) {
      const auto waited = Clock::now() - start;
      if (waited > patience) return false;
      spinning = waited < kSpinTime;
    }
    if (spinning) {
      CpuRelax();
    } else {
      std::this_thread::yield();
    }
  }
  return true;
}

std::uint32_t TagOf(std::uint64_t generation) { return static_cast<std::uint32_t>(generation); }
std::uint32_t CursorTag(std::uint64_t cursor) { return static_cast<std::uint32_t>(cursor >> 32U); }
int CursorIndex(std::uint64_t cursor) {
  return static_cast<int>(static_cast<std::uint32_t>(cursor));
}
std::uint64_t MakeCursor(std::uint32_t tag, int index) {
  return (static_cast<std::uint64_t>(tag) << 32U) | static_cast<std::uint32_t>(index);
}

}  // namespace

ThreadPool::ThreadPool(int num_threads)
    : shares_(std::make_unique<Share[]>(static_cast<std::size_t>(std::max(1, num_threads)))) {
  for (int worker = 0; worker + 1 < std::max(1, num_threads); ++worker) {
    workers_.emplace_back([this, worker] { WorkerLoop(worker); });
  }
}

ThreadPool::~ThreadPool() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& thread : workers_) thread.join();
}

bool ThreadPool::Claim(Share& share, std::uint32_t tag, int* index) {
  std::uint64_t cursor = share.cursor.load(std::memory_order_relaxed);
  // `end` is published after the cursor (StartLoop): an end of a newer loop comes with that
  // loop's cursor, so the exchange below fails for a late worker.
  while (CursorTag(cursor) == tag &&
         CursorIndex(cursor) < share.end.load(std::memory_order_acquire)) {
    if (share.cursor.compare_exchange_weak(cursor, cursor + 1, std::memory_order_acquire,
                                           std::memory_order_relaxed)) {
      *index = CursorIndex(cursor);
      return true;
    }
  }
  return false;
}

void ThreadPool::Finish(int done) {
  if (remaining_.fetch_sub(done, std::memory_order_acq_rel) == done &&
      caller_watches_.load(std::memory_order_relaxed)) {
    // Under the mutex, so the wake-up cannot slip in between the caller's check and its wait.
    const std::lock_guard<std::mutex> lock(mutex_);
    loop_done_.notify_one();
  }
}

void ThreadPool::Abandon(std::uint32_t tag) {
  const int participants = num_participants_.load(std::memory_order_relaxed);
  for (int p = 0; p < participants; ++p) {
    Share& share = shares_[p];
    const int end = share.end.load(std::memory_order_acquire);
    std::uint64_t cursor = share.cursor.load(std::memory_order_relaxed);
    while (CursorTag(cursor) == tag && CursorIndex(cursor) < end) {
      if (share.cursor.compare_exchange_weak(cursor, MakeCursor(tag, end),
                                             std::memory_order_acq_rel)) {
        Finish(end - CursorIndex(cursor));  // never run, but no longer pending
        break;
      }
    }
  }
}

void ThreadPool::Participate(std::uint64_t generation, int participant) {
  const std::uint32_t tag = TagOf(generation);
  const std::function<void(int)>* body = body_.load(std::memory_order_acquire);
  const int participants = num_participants_.load(std::memory_order_relaxed);
  int finished = 0;
  // Own share first, then what is left of the others'.
  for (int k = 0; k < participants; ++k) {
    Share& share = shares_[(participant + k) % participants];
    for (int index = 0; Claim(share, tag, &index); ++finished) {
      try {
        (*body)(index);
      } catch (...) {
        {
          const std::lock_guard<std::mutex> lock(mutex_);
          if (!error_) error_ = std::current_exception();
        }
        Abandon(tag);
      }
    }
  }
  if (finished > 0) Finish(finished);
}

void ThreadPool::StartLoop(int count, const std::function<void(int)>& body, bool caller_runs) {
  const int participants = static_cast<int>(workers_.size()) + (caller_runs ? 1 : 0);
  const std::uint64_t generation = generation_.load(std::memory_order_relaxed) + 1;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    error_ = nullptr;
    for (int p = 0; p < participants; ++p) {
      shares_[p].cursor.store(MakeCursor(TagOf(generation), ShareStart(count, participants, p)),
                              std::memory_order_relaxed);
      shares_[p].end.store(ShareStart(count, participants, p + 1), std::memory_order_release);
    }
    body_.store(&body, std::memory_order_relaxed);
    num_participants_.store(participants, std::memory_order_relaxed);
    caller_watches_.store(!caller_runs, std::memory_order_relaxed);
    remaining_.store(count, std::memory_order_relaxed);
    generation_.store(generation, std::memory_order_release);
  }
  wake_.notify_all();
}

void ThreadPool::ParallelFor(int count, const std::function<void(int)>& body) {
  if (workers_.empty()) {
    for (int i = 0; i < count; ++i) body(i);
    return;
  }
  StartLoop(count, body, true);
  Participate(generation_.load(std::memory_order_relaxed), 0);
  PollUntil([this] { return remaining_.load(std::memory_order_acquire) == 0; },
            Clock::duration::max());
  if (error_) std::rethrow_exception(error_);
}

void ThreadPool::ParallelFor(int count, const std::function<void(int)>& body,
                             const std::function<void()>& poll) {
  if (workers_.empty()) throw std::logic_error("ThreadPool: a watching caller needs a worker");
  StartLoop(count, body, false);
  {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!loop_done_.wait_for(lock, kPollInterval, [&] { return remaining_.load() == 0; })) {
      lock.unlock();
      poll();
      lock.lock();
    }
  }
  poll();
  if (error_) std::rethrow_exception(error_);
}

void ThreadPool::RunWhenIdle(std::function<void()> task) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    idle_tasks_.push_back(std::move(task));
    idle_task_count_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_one();
}

void ThreadPool::RunIdleTask() {
  std::function<void()> task;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (idle_tasks_.empty()) return;  // another worker took it
    task = std::move(idle_tasks_.front());
    idle_tasks_.pop_front();
    idle_task_count_.fetch_sub(1, std::memory_order_relaxed);
  }
  task();
}

std::uint64_t ThreadPool::AwaitLoop(std::uint64_t seen) {
  const auto news = [&] {
    return stopping_.load(std::memory_order_relaxed) ||
           generation_.load(std::memory_order_acquire) != seen ||
           idle_task_count_.load(std::memory_order_acquire) > 0;
  };
  for (;;) {
    if (!PollUntil(news, kYieldTime)) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, news);
    }
    if (stopping_) return seen;
    const std::uint64_t generation = generation_.load(std::memory_order_acquire);
    if (generation != seen) return generation;  // loops come first
    RunIdleTask();
  }
}

void ThreadPool::WorkerLoop(int worker) {
  for (std::uint64_t seen = 0, generation = 0; (generation = AwaitLoop(seen)) != seen;
       seen = generation) {
    // Participant 0 is the caller when it runs indices too.
    const int participant = worker + (caller_watches_.load(std::memory_order_relaxed) ? 0 : 1);
    Participate(generation, participant);
  }
}

int ThreadCountOrAllCores(int configured) {
  return configured > 0 ? configured
                        : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
}

void ParallelFor(int count, int threads, const std::function<void(int)>& task,
                 const std::function<void()>& poll) {
  // The caller only watches, so the pool holds one thread more than the workers.
  ThreadPool pool(std::clamp(threads, 1, std::max(1, count)) + 1);
  pool.ParallelFor(count, task, poll);
}

}  // namespace colav

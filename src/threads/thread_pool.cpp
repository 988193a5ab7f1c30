#include "src/threads/thread_pool.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace colav {
namespace {

// Polls before a worker sleeps (each poll yields the core): long enough to bridge the gap
// between two environment steps, short enough not to burn a core when the pool is idle.
constexpr int kSpinPolls = 2000;

constexpr std::chrono::milliseconds kPollInterval(100);

}  // namespace

ThreadPool::ThreadPool(int num_threads) {
  for (int worker = 1; worker < std::max(1, num_threads); ++worker) {
    workers_.emplace_back([this] { WorkerLoop(); });
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

void ThreadPool::RunClaimedIndices() {
  try {
    for (int i = next_index_.fetch_add(1, std::memory_order_relaxed); i < count_;
         i = next_index_.fetch_add(1, std::memory_order_relaxed)) {
      (*body_)(i);
    }
  } catch (...) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!error_) error_ = std::current_exception();
    next_index_.store(count_, std::memory_order_relaxed);  // stop handing out work
  }
}

void ThreadPool::StartLoop(int count, const std::function<void(int)>& body, bool caller_watches) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    body_ = &body;
    count_ = count;
    caller_watches_ = caller_watches;
    error_ = nullptr;
    next_index_.store(0, std::memory_order_relaxed);
    pending_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
}

void ThreadPool::ParallelFor(int count, const std::function<void(int)>& body) {
  if (workers_.empty()) {
    for (int i = 0; i < count; ++i) body(i);
    return;
  }
  StartLoop(count, body, false);
  RunClaimedIndices();
  while (pending_.load(std::memory_order_acquire) != 0) std::this_thread::yield();
  if (error_) std::rethrow_exception(error_);
}

void ThreadPool::ParallelFor(int count, const std::function<void(int)>& body,
                             const std::function<void()>& poll) {
  if (workers_.empty()) throw std::logic_error("ThreadPool: a watching caller needs a worker");
  StartLoop(count, body, true);
  {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!workers_done_.wait_for(lock, kPollInterval, [&] { return pending_.load() == 0; })) {
      lock.unlock();
      poll();
      lock.lock();
    }
  }
  poll();
  if (error_) std::rethrow_exception(error_);
}

bool ThreadPool::WaitForWork(std::uint64_t seen) {
  for (int poll = 0; poll < kSpinPolls; ++poll) {
    if (stopping_.load(std::memory_order_relaxed)) return false;
    if (generation_.load(std::memory_order_acquire) != seen) return true;
    std::this_thread::yield();
  }
  std::unique_lock<std::mutex> lock(mutex_);
  wake_.wait(lock, [&] { return stopping_ || generation_.load() != seen; });
  return !stopping_;
}

void ThreadPool::WorkerLoop() {
  std::uint64_t seen = 0;
  while (WaitForWork(seen)) {
    seen = generation_.load(std::memory_order_acquire);
    const bool caller_watches = caller_watches_;
    RunClaimedIndices();
    // The last worker wakes a watching caller; under the mutex, so the wake-up cannot slip in
    // between the caller's check and its wait.
    if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1 && caller_watches) {
      const std::lock_guard<std::mutex> lock(mutex_);
      workers_done_.notify_one();
    }
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

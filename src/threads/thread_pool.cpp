#include "src/threads/thread_pool.h"

#include <algorithm>

namespace colav {
namespace {

// Polls before a worker sleeps (each poll yields the core): long enough to bridge the gap
// between two environment steps, short enough not to burn a core when the pool is idle.
constexpr int kSpinPolls = 2000;

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
  }
}

void ThreadPool::ParallelFor(int count, const std::function<void(int)>& body) {
  if (workers_.empty()) {
    for (int i = 0; i < count; ++i) body(i);
    return;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    body_ = &body;
    count_ = count;
    error_ = nullptr;
    next_index_.store(0, std::memory_order_relaxed);
    pending_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  RunClaimedIndices();
  while (pending_.load(std::memory_order_acquire) != 0) std::this_thread::yield();
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
    RunClaimedIndices();
    pending_.fetch_sub(1, std::memory_order_acq_rel);
  }
}

}  // namespace colav

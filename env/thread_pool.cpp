#include "env/thread_pool.h"

#include <algorithm>

namespace colav {

ThreadPool::ThreadPool(int num_threads) {
  for (int worker = 1; worker < std::max(1, num_threads); ++worker) {
    workers_.emplace_back([this, worker] { WorkerLoop(worker); });
  }
}

ThreadPool::~ThreadPool() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (std::thread& thread : workers_) thread.join();
}

void ThreadPool::RunChunk(int chunk) {
  const int chunks = num_threads();
  const int begin = count_ * chunk / chunks;
  const int end = count_ * (chunk + 1) / chunks;
  try {
    for (int i = begin; i < end; ++i) (*body_)(i);
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
    pending_ = static_cast<int>(workers_.size());
    error_ = nullptr;
    ++generation_;
  }
  work_ready_.notify_all();
  RunChunk(0);
  std::unique_lock<std::mutex> lock(mutex_);
  work_done_.wait(lock, [this] { return pending_ == 0; });
  if (error_) std::rethrow_exception(error_);
}

void ThreadPool::WorkerLoop(int worker) {
  std::uint64_t seen = 0;
  while (true) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      work_ready_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
    }
    RunChunk(worker);
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      --pending_;
    }
    work_done_.notify_one();
  }
}

}  // namespace colav

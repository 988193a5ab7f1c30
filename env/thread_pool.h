// A fixed pool of worker threads that runs one parallel loop at a time; the calling thread
// takes part. Small and allocation-free per call, for stepping a few worlds every few
// microseconds.
#pragma once

#include <atomic>
#include <condition_variable>
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

  /// Calls body(i) for i in [0, count), split into contiguous chunks, one per thread; returns
  /// when all calls are done. Exceptions of body are rethrown in the caller.
  void ParallelFor(int count, const std::function<void(int)>& body);

 private:
  void WorkerLoop(int worker);
  void RunChunk(int chunk);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable work_ready_;
  std::condition_variable work_done_;
  const std::function<void(int)>* body_ = nullptr;
  int count_ = 0;
  std::uint64_t generation_ = 0;
  int pending_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
};

}  // namespace colav

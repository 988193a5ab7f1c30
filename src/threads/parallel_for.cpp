#include "src/threads/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace colav {

void ParallelFor(std::int64_t count, int threads, const std::function<void(std::int64_t)>& task,
                 const std::function<void()>& poll) {
  std::atomic<std::int64_t> next{0};
  std::mutex mutex;  // guards running and failure
  std::condition_variable finished;
  int running = static_cast<int>(std::clamp<std::int64_t>(count, 1, std::max(1, threads)));
  std::exception_ptr failure;
  const auto worker = [&] {
    for (std::int64_t i = next++; i < count; i = next++) {
      try {
        task(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        next = count;  // stop handing out work
      }
    }
    const std::lock_guard<std::mutex> lock(mutex);
    --running;
    finished.notify_one();
  };
  std::vector<std::thread> workers;
  for (int t = running; t > 0; --t) workers.emplace_back(worker);
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return running == 0; })) {
      lock.unlock();
      poll();
      lock.lock();
    }
  }
  for (std::thread& thread : workers) thread.join();
  poll();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace colav

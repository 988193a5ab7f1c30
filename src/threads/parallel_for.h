// Runs independent, individually seeded tasks (one scan, one episode) on a few threads. Each
// task's result depends only on its index, so the output does not depend on the thread count.
#pragma once

#include <cstdint>
#include <functional>

namespace colav {

/// Calls task(i) for i in [0, count) on `threads` threads. While they run, the calling thread
/// calls `poll` about ten times a second (progress display). The first exception a task throws is
/// rethrown here after all threads have stopped.
void ParallelFor(std::int64_t count, int threads, const std::function<void(std::int64_t)>& task,
                 const std::function<void()>& poll);

}  // namespace colav

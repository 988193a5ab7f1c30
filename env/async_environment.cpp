#include "env/async_environment.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <string>

#include "src/fixed_queue.h"
#include "src/threads/cpu_relax.h"
#include "src/threads/spin_lock.h"

namespace colav {
namespace {

using Clock = std::chrono::steady_clock;

// A thread with nothing to do spins this long before it sleeps, as ThreadPool's workers do: the
// gap between a Recv and the next Send (a policy forward, a Python loop iteration) is 10-30 µs,
// and a sleep and wake-up cost about as much as a step.
constexpr auto kSpinTime = std::chrono::microseconds(100);
constexpr int kPollsPerClockRead = 64;
// How far into the queue a runner looks for a world it stepped last, and how often a task may be
// passed over for one (TaskQueues::Pop).
constexpr int kAffinityLookahead = 16;
constexpr int kMaxPassOvers = 4;

// Polls `ready` for up to kSpinTime; returns whether it holds.
template <typename Ready>
bool SpinUntil(const Ready& ready) {
  const auto start = Clock::now();
  for (int poll = 1; !ready(); ++poll) {
    if (poll % kPollsPerClockRead == 0 && Clock::now() - start > kSpinTime) return false;
    CpuRelax();
  }
  return true;
}

int CheckedWorldCount(int num_envs) {
  if (num_envs < 1) {
    throw std::invalid_argument("AsyncEnvironmentPool: num_envs " + std::to_string(num_envs) +
                                " is not >= 1");
  }
  return num_envs;
}

int CheckedBatchSize(int batch_size, int num_envs) {
  if (batch_size < 1 || batch_size > num_envs) {
    throw std::invalid_argument("AsyncEnvironmentPool: batch_size " + std::to_string(batch_size) +
                                " is outside [1, " + std::to_string(num_envs) +
                                "] (1 to the number of worlds)");
  }
  return batch_size;
}

}  // namespace

struct AsyncEnvironmentPool::Task {
  int world = 0;
  bool reset = false;   ///< start the world's chosen episode instead of stepping it
  int passed_over = 0;  ///< times a runner took a task queued after it
};

// The state the threads share. A runner is a thread that steps worlds: 0 the caller, k >= 1 the
// worker k. A runner with nothing to do spins a little, then sleeps on a condition variable, and
// whoever gives it something to do wakes it only if it sleeps. The fields a runner touches on
// every task are next to the lock, so that taking it brings them into the core's cache too.
class AsyncEnvironmentPool::TaskQueues {
 public:
  TaskQueues(int num_envs, int runners)
      : tasks(num_envs),
        done(num_envs),
        preparations(num_envs),
        preparation_queued(num_envs, false),
        last_runner(num_envs) {
    for (int world = 0; world < num_envs; ++world) last_runner[world] = world % runners;
  }

  SpinLock lock;
  // Guarded by lock:
  FixedQueue<Task> tasks;
  FixedQueue<int> done;  ///< worlds whose task is finished, not yet received
  /// Worlds whose next episode is to be prepared (BatchedEnvironment::BuildNextEpisode), which
  /// the workers do before any step: an ending episode then swaps in the prepared one instead of
  /// resetting for as long as a hundred steps. A caller that did that reset in Recv left the
  /// workers without actions meanwhile (perf: 275 context switches a second, against 20 for the
  /// synchronous pool); interleaved runs gave 1.85x and 1.90x one thread with the preparations
  /// first, 1.78x and 1.62x with them run only when no step was queued.
  FixedQueue<int> preparations;
  std::vector<bool> preparation_queued;  ///< per world: in preparations
  int running = 0;                       ///< tasks taken from the queue and not finished
  std::vector<int> last_runner;          ///< per world
  std::exception_ptr error;  ///< the first error a task raised since it was last reported
  // Written under the lock, also polled without it. Each sleep flag and the count its sleeper
  // waits on are sequentially consistent: a waker cannot miss a runner about to sleep.
  std::atomic<int> queued{0};              ///< tasks.size() + preparations.size()
  std::atomic<std::uint64_t> finished{0};  ///< tasks finished so far
  std::atomic<bool> stopping{false};
  std::atomic<int> sleeping_workers{0};
  std::atomic<bool> caller_sleeps{false};

  /// Takes a task for `runner`, counting it as running; under the lock. Among the first few
  /// queued it takes one of a world it stepped last, if any, since a world whose data stays in
  /// one core's cache steps faster; but not past a task passed over a few times already, which
  /// would otherwise wait as long as the caller is busy elsewhere.
  Task Pop(int runner) {
    int chosen = 0;
    if (tasks[0].passed_over < kMaxPassOvers) {
      const int lookahead = std::min(tasks.size(), kAffinityLookahead);
      while (chosen < lookahead && last_runner[tasks[chosen].world] != runner) ++chosen;
      if (chosen == lookahead) chosen = 0;
    }
    for (int k = 0; k < chosen; ++k) ++tasks[k].passed_over;
    const Task task = tasks.Remove(chosen);
    queued.store(tasks.size() + preparations.size());
    ++running;
    return task;
  }

  /// Hands back a world whose task `runner` ran; under the lock. Returns whether the caller
  /// sleeps and must be woken (WakeCaller, best after unlocking).
  bool Finish(int world, int runner, const std::exception_ptr& task_error) {
    if (task_error && !error) error = task_error;
    --running;
    last_runner[world] = runner;
    done.Push(world);
    finished.fetch_add(1);
    return runner != 0 && caller_sleeps.load();
  }

  /// Queues a task for each of worlds[0..count) and wakes the sleeping workers.
  void Push(const std::int32_t* worlds, int count, bool reset) {
    {
      const std::lock_guard<SpinLock> hold(lock);
      for (int k = 0; k < count; ++k) tasks.Push({worlds[k], reset, 0});
      queued.store(tasks.size() + preparations.size());
    }
    if (sleeping_workers.load() > 0) Notify(work_ready);
  }

  /// Queues the preparation of world's next episode, unless it is queued already (it then
  /// prepares the episode wanted when it runs).
  void QueuePreparation(int world) {
    {
      const std::lock_guard<SpinLock> hold(lock);
      if (preparation_queued[world]) return;
      preparation_queued[world] = true;
      preparations.Push(world);
      queued.store(tasks.size() + preparations.size());
    }
    if (sleeping_workers.load() > 0) Notify(work_ready);
  }

  /// Takes a world to prepare; under the lock.
  int PopPreparation() {
    const int world = preparations.Pop();
    preparation_queued[world] = false;
    queued.store(tasks.size() + preparations.size());
    return world;
  }

  /// Returns once there may be a task for a worker, or the pool stops.
  void AwaitTasks() {
    const auto news = [this] { return queued.load() > 0 || stopping.load(); };
    if (SpinUntil(news)) return;
    std::unique_lock<std::mutex> sleep(sleep_mutex);
    sleeping_workers.fetch_add(1);
    work_ready.wait(sleep, news);
    sleeping_workers.fetch_sub(1);
  }

  /// Returns once a task has finished since `finished` counted `seen`.
  void AwaitFinish(std::uint64_t seen) {
    const auto news = [this, seen] { return finished.load() != seen; };
    if (SpinUntil(news)) return;
    std::unique_lock<std::mutex> sleep(sleep_mutex);
    caller_sleeps.store(true);
    progress.wait(sleep, news);
    caller_sleeps.store(false);
  }

  void WakeCaller() { Notify(progress); }

  void Stop() {
    stopping.store(true);
    Notify(work_ready);
  }

 private:
  /// Wakes the sleepers of `condition`; taking the mutex first makes sure a sleeper that saw
  /// nothing to do is waiting on it, not about to.
  void Notify(std::condition_variable& condition) {
    { const std::lock_guard<std::mutex> hold(sleep_mutex); }
    condition.notify_all();
  }

  std::mutex sleep_mutex;
  std::condition_variable work_ready;  // for sleeping workers
  std::condition_variable progress;    // for the sleeping caller: a task finished
};

AsyncEnvironmentPool::AsyncEnvironmentPool(const EnvironmentConfig& config, int num_envs,
                                           int batch_size, int num_threads, std::uint64_t seed)
    : AsyncEnvironmentPool(
          std::make_unique<BatchedEnvironment>(config, CheckedWorldCount(num_envs), 1, seed),
          batch_size, num_threads) {}

AsyncEnvironmentPool::AsyncEnvironmentPool(
    const EnvironmentConfig& config, const std::vector<TrainingScenarioConfig>& world_scenarios,
    int batch_size, int num_threads, std::uint64_t seed)
    : AsyncEnvironmentPool(std::make_unique<BatchedEnvironment>(config, world_scenarios, 1, seed),
                           batch_size, num_threads) {}

AsyncEnvironmentPool::AsyncEnvironmentPool(const EnvironmentConfig& config,
                                           const std::vector<Scenario>& scenarios, int batch_size,
                                           int num_threads)
    : AsyncEnvironmentPool(std::make_unique<BatchedEnvironment>(config, scenarios, 1), batch_size,
                           num_threads) {}

AsyncEnvironmentPool::AsyncEnvironmentPool(std::unique_ptr<BatchedEnvironment> worlds,
                                           int batch_size, int num_threads)
    : OwnedStepResults(CheckedBatchSize(batch_size, worlds->num_envs()),
                       worlds->observation_size()),
      worlds_(std::move(worlds)),
      batch_size_(batch_size),  // checked above
      actions_(static_cast<std::size_t>(worlds_->num_envs()) * kActionSize, 0.0),
      in_flight_(worlds_->num_envs(), false),
      env_ids_(batch_size_, 0) {
  if (num_threads < 1) {
    throw std::invalid_argument("AsyncEnvironmentPool: num_threads " + std::to_string(num_threads) +
                                " is not >= 1");
  }
  const int runners = std::min(num_threads, num_envs());
  queues_ = std::make_unique<TaskQueues>(num_envs(), runners);
  if (runners > 1) {  // else no worker could prepare them
    worlds_->PrepareNextEpisodesWith([this](int world) { queues_->QueuePreparation(world); });
  }
  for (int runner = 1; runner < runners; ++runner) {
    workers_.emplace_back([this, runner] {
      RunTasksUntil(runner, [](TaskQueues& queues) { return queues.stopping.load(); });
    });
  }
}

AsyncEnvironmentPool::~AsyncEnvironmentPool() {
  queues_->Stop();
  for (std::thread& worker : workers_) worker.join();
}

void AsyncEnvironmentPool::Reset(std::optional<std::uint64_t> seed) {
  // The worlds must be still before their episodes are chosen, and a sent step is played so that
  // where a world stands depends only on the actions it was sent.
  RunTasksUntil(0, [](TaskQueues& queues) {
    if (queues.tasks.size() > 0 || queues.running > 0) return false;
    queues.done.Clear();
    queues.error = nullptr;
    return true;
  });
  worlds_->ChooseResetEpisodes(seed);
  std::vector<std::int32_t> all(num_envs());
  std::iota(all.begin(), all.end(), 0);
  std::fill(in_flight_.begin(), in_flight_.end(), true);
  in_flight_count_ = num_envs();
  started_ = true;
  queues_->Push(all.data(), num_envs(), true);
}

void AsyncEnvironmentPool::Send(const float* actions, const std::int32_t* env_ids, int count) {
  SendActions(actions, env_ids, count);
}

void AsyncEnvironmentPool::Send(const double* actions, const std::int32_t* env_ids, int count) {
  SendActions(actions, env_ids, count);
}

template <typename Action>
void AsyncEnvironmentPool::SendActions(const Action* actions, const std::int32_t* env_ids,
                                       int count) {
  if (!started_) throw std::logic_error("AsyncEnvironmentPool: Send before the first Reset");
  MarkSent(env_ids, count);
  for (int k = 0; k < count; ++k) {
    // Widened here as BatchedEnvironment widens a float action, so both step alike.
    std::copy(actions + static_cast<std::ptrdiff_t>(k) * kActionSize,
              actions + static_cast<std::ptrdiff_t>(k + 1) * kActionSize,
              &actions_[static_cast<std::size_t>(env_ids[k]) * kActionSize]);
  }
  queues_->Push(env_ids, count, false);
}

void AsyncEnvironmentPool::MarkSent(const std::int32_t* env_ids, int count) {
  if (count < 0 || count > num_envs()) {
    throw std::invalid_argument("AsyncEnvironmentPool: " + std::to_string(count) +
                                " actions sent to " + std::to_string(num_envs()) + " worlds");
  }
  for (int k = 0; k < count; ++k) {
    const std::int32_t world = env_ids[k];
    std::string error;
    if (world < 0 || world >= num_envs()) {
      error =
          "env id " + std::to_string(world) + " is outside [0, " + std::to_string(num_envs()) + ")";
    } else if (in_flight_[world]) {
      error = "env id " + std::to_string(world) +
              " has not come back from Recv since it was last sent an action or reset";
    }
    if (!error.empty()) {
      for (int j = 0; j < k; ++j) in_flight_[env_ids[j]] = false;
      throw std::invalid_argument("AsyncEnvironmentPool: " + error);
    }
    in_flight_[world] = true;
  }
  in_flight_count_ += count;
}

void AsyncEnvironmentPool::Recv() { Recv({OwnOutputs(), env_ids_.data()}); }

void AsyncEnvironmentPool::Recv(const AsyncBatchOutputs& outputs) {
  if (in_flight_count_ < batch_size_) {
    throw std::logic_error(
        "AsyncEnvironmentPool: Recv with worlds stepping: " + std::to_string(in_flight_count_) +
        ", fewer than the batch of " + std::to_string(batch_size_) + " (send them actions first)");
  }
  std::exception_ptr error;
  RunTasksUntil(0, [this, &outputs, &error](TaskQueues& queues) {
    if (queues.done.size() < batch_size_) return false;
    for (int row = 0; row < batch_size_; ++row) outputs.env_ids[row] = queues.done.Pop();
    std::swap(error, queues.error);
    return true;
  });
  std::sort(outputs.env_ids, outputs.env_ids + batch_size_);
  for (int row = 0; row < batch_size_; ++row) in_flight_[outputs.env_ids[row]] = false;
  in_flight_count_ -= batch_size_;
  if (error) std::rethrow_exception(error);
  CopyResults(outputs);
}

void AsyncEnvironmentPool::CopyResults(const AsyncBatchOutputs& outputs) {
  const int size = observation_size();
  const auto row_of = [size](const float* rows, int index) {
    return rows + static_cast<std::ptrdiff_t>(index) * size;
  };
  const BatchedOutputs& to = outputs.results;
  for (int row = 0; row < batch_size_; ++row) {
    const int world = outputs.env_ids[row];
    std::copy_n(row_of(worlds_->observations(), world), size,
                to.observations + static_cast<std::ptrdiff_t>(row) * size);
    to.rewards[row] = worlds_->rewards()[world];
    to.terminated[row] = worlds_->terminated()[world];
    to.truncated[row] = worlds_->truncated()[world];
    if (to.terminated[row] || to.truncated[row]) {
      std::copy_n(row_of(worlds_->final_observations(), world), size,
                  to.final_observations + static_cast<std::ptrdiff_t>(row) * size);
    }
    finished_episodes_[row] = worlds_->finished_episodes()[world];
  }
}

template <typename Stop>
void AsyncEnvironmentPool::RunTasksUntil(int runner, const Stop& stop) {
  TaskQueues& queues = *queues_;
  std::unique_lock<SpinLock> hold(queues.lock);
  while (!stop(queues)) {
    if (runner != 0 && queues.preparations.size() > 0) {
      // Not the caller: it would hold up the batch it waits for.
      const int world = queues.PopPreparation();
      hold.unlock();
      worlds_->BuildNextEpisode(world);
      hold.lock();
    } else if (queues.tasks.size() > 0) {
      const Task task = queues.Pop(runner);
      hold.unlock();
      const std::exception_ptr error = Run(task);
      hold.lock();  // once for finishing this task and taking the next
      if (queues.Finish(task.world, runner, error)) {
        hold.unlock();
        queues.WakeCaller();
        hold.lock();
      }
    } else if (runner == 0) {  // the rest is in the workers' hands (only the caller queues tasks)
      const std::uint64_t finished = queues.finished.load();
      hold.unlock();
      queues.AwaitFinish(finished);
      hold.lock();
    } else {
      hold.unlock();
      queues.AwaitTasks();
      hold.lock();
    }
  }
}

std::exception_ptr AsyncEnvironmentPool::Run(const Task& task) {
  try {
    if (task.reset) {
      worlds_->ResetWorld(task.world);
    } else {
      worlds_->StepWorld(task.world, &actions_[static_cast<std::size_t>(task.world) * kActionSize]);
    }
  } catch (...) {
    return std::current_exception();  // reported by a Recv; the world still comes back
  }
  return nullptr;
}

}  // namespace colav

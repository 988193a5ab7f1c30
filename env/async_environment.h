// N worlds stepped asynchronously, EnvPool style: Recv returns the first batch_size worlds whose
// step is done, Send queues their next actions, and the threads step each world as soon as its
// action arrives instead of waiting for the whole batch at a barrier every step.
#pragma once

#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include "env/batched_environment.h"

namespace colav {

/// Where Recv writes a batch, in memory the caller owns: batch_size rows each.
struct AsyncBatchOutputs {
  BatchedOutputs results;           ///< row r holds world env_ids[r]'s results
  std::int32_t* env_ids = nullptr;  ///< batch_size
};

/// Every world plays exactly the episodes it plays in a BatchedEnvironment of the same seed (or
/// scenarios) under the same actions, with the same auto-reset: the worlds are a
/// BatchedEnvironment's, stepped one at a time (BatchedEnvironment::StepWorld). Only which worlds
/// a Recv returns depends on timing; within a batch the rows are in increasing env id, so with
/// batch_size == num_envs every Recv returns every world, in the synchronous environment's order.
///
/// num_threads counts the caller, as BatchedEnvironment's does: num_threads - 1 worker threads
/// step the worlds whose actions are queued, and the caller steps queued worlds too while it waits
/// in Recv (EnvPool's workers are all extra threads; here a 2-core machine runs 2 threads
/// stepping, not 2 plus a waiting caller). One thread calls Reset, Send and Recv.
/// Its own results (OwnedStepResults) have one row per batch row, world env_ids()[row].
class AsyncEnvironmentPool : public OwnedStepResults {
 public:
  /// num_envs worlds of the paper's training scenario, seeded as BatchedEnvironment's. Throws
  /// std::invalid_argument unless 1 <= batch_size <= num_envs and num_threads >= 1.
  AsyncEnvironmentPool(const EnvironmentConfig& config, int num_envs, int batch_size,
                       int num_threads, std::uint64_t seed);
  /// One world per entry of `world_scenarios`, each generating its episodes from that variant of
  /// the training scenario (BatchedEnvironment's mix of training worlds); seeds as above.
  AsyncEnvironmentPool(const EnvironmentConfig& config,
                       const std::vector<TrainingScenarioConfig>& world_scenarios, int batch_size,
                       int num_threads, std::uint64_t seed);
  /// One world per scenario, replaying it in every episode.
  AsyncEnvironmentPool(const EnvironmentConfig& config, const std::vector<Scenario>& scenarios,
                       int batch_size, int num_threads);
  /// Stops the threads after the steps they are running; queued steps are dropped.
  ~AsyncEnvironmentPool();
  AsyncEnvironmentPool(const AsyncEnvironmentPool&) = delete;
  AsyncEnvironmentPool& operator=(const AsyncEnvironmentPool&) = delete;

  int num_envs() const { return worlds_->num_envs(); }
  int batch_size() const { return batch_size_; }
  int observation_size() const { return worlds_->observation_size(); }

  /// Queues a new episode in every world, as BatchedEnvironment::Reset chooses them (EnvPool's
  /// async_reset); Recv then returns the reset observations. Steps already sent are played
  /// first, and results not yet received are dropped.
  void Reset(std::optional<std::uint64_t> seed = std::nullopt);

  /// Queues the next step of worlds env_ids[0..count) with actions (count x kActionSize,
  /// row-major, clipped to [-1, 1]; floats are widened to double as BatchedEnvironment does).
  /// Each world must have come back from a Recv since it was last sent an action or reset:
  /// std::invalid_argument names the first that has not, or an id out of range.
  void Send(const float* actions, const std::int32_t* env_ids, int count);
  void Send(const double* actions, const std::int32_t* env_ids, int count);

  /// Waits until batch_size worlds are done and writes their results to the pool's own buffers
  /// (the accessors below): observations, rewards, terminated and truncated as
  /// BatchedEnvironment::Step gives them, final observations where an episode ended. Throws
  /// std::logic_error if fewer than batch_size worlds are stepping (they would never come), and
  /// rethrows an error a world's step raised.
  void Recv();
  /// The same, with the results written to `outputs`.
  void Recv(const AsyncBatchOutputs& outputs);

  /// The worlds of the rows of the last Recv that wrote to the pool's own buffers.
  const std::int32_t* env_ids() const { return env_ids_.data(); }

 private:
  struct Task;
  class TaskQueues;  // the queues of tasks and of finished worlds the threads share

  AsyncEnvironmentPool(std::unique_ptr<BatchedEnvironment> worlds, int batch_size, int num_threads);
  template <typename Action>
  void SendActions(const Action* actions, const std::int32_t* env_ids, int count);
  /// Marks the worlds as stepping; throws std::invalid_argument (marking none) if one cannot be.
  void MarkSent(const std::int32_t* env_ids, int count);
  /// Runs queued tasks as runner `runner` (0 the caller, k >= 1 the worker k) until
  /// stop(queues), called under the queues' lock, returns true; stop may take what it waited for.
  template <typename Stop>
  void RunTasksUntil(int runner, const Stop& stop);
  /// Resets or steps a world; returns what it threw.
  std::exception_ptr Run(const Task& task);
  /// Copies the results of worlds outputs.env_ids into the rows of outputs.
  void CopyResults(const AsyncBatchOutputs& outputs);

  std::unique_ptr<BatchedEnvironment> worlds_;  // one thread: this pool's threads step them
  int batch_size_;
  std::vector<double> actions_;  ///< num_envs x kActionSize, each world's next action
  /// Per world, seen by the calling thread only: sent (or reset) and not yet received.
  std::vector<bool> in_flight_;
  int in_flight_count_ = 0;
  bool started_ = false;

  std::vector<std::int32_t> env_ids_;

  std::unique_ptr<TaskQueues> queues_;
  std::vector<std::thread> workers_;  // last: started once everything they use exists
};

}  // namespace colav

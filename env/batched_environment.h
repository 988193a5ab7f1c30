// N worlds stepped together by a thread pool, auto-resetting (EnvPool style).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "env/critic_observation.h"
#include "env/environment_spec.h"
#include "env/scenario.h"
#include "env/step_results.h"
#include "env/training_scenario.h"

namespace colav {

class Environment;
class ThreadPool;

/// The seed episode `episode` (counted from 0) of world `world` of a BatchedEnvironment built
/// with `seed` is generated from.
std::uint64_t TrainingEpisodeSeed(std::uint64_t seed, int world, std::uint64_t episode);

/// The seed of test scenario k of an evaluation with `master_seed` (evaluate, the Python module):
/// DeriveSeed(master_seed, "test-scenario", k). Every model meets the same worlds.
std::uint64_t TestScenarioSeed(std::uint64_t master_seed, std::uint64_t k);

/// What a world of a BatchedEnvironment has played since its episode started: enough to rebuild
/// it bit for bit (BatchedEnvironment::Restore), since an episode is a pure function of its seed
/// and the actions applied to it. A few kilobytes, where a copy of the world would be megabytes.
struct WorldHistory {
  std::uint64_t episode = 0;    ///< the episode's index in its world
  std::vector<double> actions;  ///< kActionSize per step, as the world applied them (clipped)
};

/// With more than one thread, an idle worker prepares each world's next episode while the worlds
/// step (ThreadPool::RunWhenIdle), so a world whose episode ends swaps it in instead of holding up
/// the step with a reset, which costs about a hundred steps. The prepared episode is the one the
/// world would reset to, so results do not depend on it.
/// Its own results (OwnedStepResults) have one row per world.
class BatchedEnvironment : public OwnedStepResults {
 public:
  /// num_envs worlds of the paper's training scenario; episode k of world i is generated from
  /// TrainingEpisodeSeed(seed, i, k), so a run is a pure function of `seed`.
  BatchedEnvironment(const EnvironmentConfig& config, int num_envs, int num_threads,
                     std::uint64_t seed);
  /// One world per entry of `world_scenarios`, each generating its episodes from that variant of
  /// the training scenario (a mix of training worlds); seeds as above.
  BatchedEnvironment(const EnvironmentConfig& config,
                     const std::vector<TrainingScenarioConfig>& world_scenarios, int num_threads,
                     std::uint64_t seed);
  /// One world per scenario, each replaying its scenario in every episode (scenario files, the
  /// evaluation's test worlds).
  BatchedEnvironment(const EnvironmentConfig& config, const std::vector<Scenario>& scenarios,
                     int num_threads);
  ~BatchedEnvironment();
  BatchedEnvironment(const BatchedEnvironment&) = delete;
  BatchedEnvironment& operator=(const BatchedEnvironment&) = delete;

  int num_envs() const { return num_envs_; }
  /// Floats per observation row: ObservationSize(config).
  int observation_size() const { return observation_size_; }

  /// Starts a new episode in every world: episode 0 on the first call, then the next episode of
  /// each world (a running one is abandoned). With a seed, the worlds start over from episode 0
  /// of that seed. observations() then holds the reset observations.
  void Reset(std::optional<std::uint64_t> seed = std::nullopt);
  /// The same, with the results written to `outputs`.
  void Reset(std::optional<std::uint64_t> seed, const BatchedOutputs& outputs);

  /// Steps every world with actions (num_envs x kActionSize, row-major, clipped to [-1, 1]).
  /// A world whose episode ends is reset at once: observations() holds its new reset
  /// observation and final_observations() the last observation of the finished episode.
  void Step(const float* actions);
  /// The same, with the results written to `outputs`; double actions are used as they are (a
  /// float action is widened to double first, so both give the same step for float values).
  void Step(const float* actions, const BatchedOutputs& outputs);
  void Step(const double* actions, const BatchedOutputs& outputs);

  // One world at a time, for AsyncEnvironmentPool, which steps each world on whichever of its
  // threads gets the world's action. With one thread (so no pool worker touches the worlds),
  // ResetWorld and StepWorld of different worlds, and BuildNextEpisode of any, may run at once
  // on different threads: each writes only its world's row of the environment's own results.
  /// Reset's first half: chooses each world's next episode (episode 0 of `seed`, else the one
  /// after its current episode), which ResetWorld then starts.
  void ChooseResetEpisodes(std::optional<std::uint64_t> seed);
  /// Reset's second half for one world: starts its chosen episode.
  void ResetWorld(int world);
  /// Step for one world: action is kActionSize values (clipped to [-1, 1]).
  void StepWorld(int world, const double* action);
  /// From now on a world's next episode is prepared by whoever `schedule(world)` arranges to
  /// call BuildNextEpisode(world), instead of by this environment's idle workers (the worker
  /// threads of an AsyncEnvironmentPool, which has no barrier to wait at).
  void PrepareNextEpisodesWith(std::function<void(int world)> schedule);
  /// Prepares world's next episode, unless it is no longer wanted; any thread, once per schedule.
  void BuildNextEpisode(int world);

  /// From now on each reset and step also writes every world's critic observation of its
  /// `vessels` nearest moving vessels (critic_observation.h): critic_observations(), one row of
  /// critic_observation_size() floats per world, and for a world whose episode just ended
  /// final_critic_observations(), its last state's. For train_ppo's privileged critic.
  void ObserveVesselsForCritic(int vessels);
  int critic_observation_size() const { return CriticObservationSize(critic_vessels_); }
  const float* critic_observations() const { return critic_observations_.data(); }
  const float* final_critic_observations() const { return final_critic_observations_.data(); }

  /// Every world's history, for a checkpoint.
  const std::vector<WorldHistory>& histories() const { return histories_; }
  /// Puts every world back where `histories` (one per world, from histories()) left it by
  /// replaying its actions from the start of its episode; observations() then holds the worlds'
  /// current observations. The other results of the last Step are not restored. Throws
  /// std::invalid_argument if `histories` cannot come from this environment (another world count,
  /// an action outside [-1, 1], an episode that ends during the replay).
  void Restore(const std::vector<WorldHistory>& histories);

 private:
  BatchedEnvironment(const EnvironmentConfig& config, int num_envs, int num_threads,
                     std::uint64_t seed,
                     const std::vector<std::shared_ptr<const ScenarioSource>>& sources);
  struct NextEpisode;

  std::uint64_t EpisodeSeed(int world, std::uint64_t episode) const;
  /// Starts world `world`'s episode histories_[world].episode, writing its first observation.
  void StartEpisode(int world, float* observation);
  /// Swaps in the prepared next episode if it is that episode; false otherwise.
  bool TakeNextEpisode(int world, float* observation);
  /// Queues the preparation of the episode after the current one.
  void PrepareNextEpisode(int world);
  template <typename Action>
  void StepAll(const Action* actions, const BatchedOutputs& outputs);
  void ResetWorld(int world, const BatchedOutputs& outputs);
  template <typename Action>
  void StepWorld(int world, const Action* action, const BatchedOutputs& outputs);
  void ReplayWorld(int world, const WorldHistory& history);
  /// World `world`'s row of `rows` (critic_observations_ or final_critic_observations_) from its
  /// current state; nothing unless ObserveVesselsForCritic was called.
  void WriteCriticObservation(int world, std::vector<float>& rows) const;
  /// Orders each thread's share of the worlds by the cost of their last step, dearest first, so
  /// the world a thread may still be stepping when the other has nothing left is its cheapest
  /// (the wait at the end of a step was about 8 % of the threads' time).
  void OrderSharesByCost();

  int num_envs_;
  int observation_size_;
  std::uint64_t seed_;
  bool started_ = false;
  std::vector<std::unique_ptr<Environment>> worlds_;
  std::vector<WorldHistory> histories_;
  std::vector<std::unique_ptr<NextEpisode>> next_episodes_;
  std::unique_ptr<ThreadPool> pool_;               // after what its idle tasks use: destroyed first
  std::function<void(int)> schedule_preparation_;  ///< if set, used instead of pool_
  /// The world stepped as loop index i; each thread's share as ThreadPool::ShareStart splits them.
  std::vector<int> step_order_;
  std::vector<std::uint64_t> step_cost_;  ///< of each world's last step, in clock ticks
  int critic_vessels_ = 0;                ///< ObserveVesselsForCritic's; 0: none written
  std::vector<float> critic_observations_, final_critic_observations_;
};

}  // namespace colav

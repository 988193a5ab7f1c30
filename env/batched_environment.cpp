#include "env/batched_environment.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#if defined(__x86_64__)
#include <x86intrin.h>
#endif

#include "env/environment.h"
#include "env/scenario_file.h"
#include "env/training_scenario.h"
#include "src/seeding.h"
#include "src/threads/thread_pool.h"

namespace colav {

struct BatchedEnvironment::NextEpisode {
  enum State : int { kEmpty, kQueued, kBuilding, kReady };
  std::unique_ptr<Environment> environment;
  std::vector<float> observation;
  std::uint64_t seed = 0;  ///< of the episode it holds or is to hold
  std::atomic<int> state{kEmpty};
};

namespace {

// Clock ticks, only compared with each other: the time-stamp counter where there is one (a read
// costs less than a steady_clock::now() call, and this runs twice per world and step).
std::uint64_t Ticks() {
#if defined(__x86_64__)
  return __rdtsc();
#else
  return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
}

std::vector<std::shared_ptr<const ScenarioSource>> SharedTrainingSource(int num_envs) {
  return std::vector<std::shared_ptr<const ScenarioSource>>(
      num_envs, std::make_shared<TrainingScenarioGenerator>());
}

// One source per item: a Source made from it (a training scenario's generator, a fixed scenario).
template <typename Source, typename Item>
std::vector<std::shared_ptr<const ScenarioSource>> SourcesOf(const std::vector<Item>& items) {
  std::vector<std::shared_ptr<const ScenarioSource>> sources;
  sources.reserve(items.size());
  for (const Item& item : items) sources.push_back(std::make_shared<Source>(item));
  return sources;
}

}  // namespace

BatchedEnvironment::BatchedEnvironment(const EnvironmentConfig& config, int num_envs,
                                       int num_threads, std::uint64_t seed)
    : BatchedEnvironment(config, num_envs, num_threads, seed, SharedTrainingSource(num_envs)) {}

BatchedEnvironment::BatchedEnvironment(const EnvironmentConfig& config,
                                       const std::vector<TrainingScenarioConfig>& world_scenarios,
                                       int num_threads, std::uint64_t seed)
    : BatchedEnvironment(config, static_cast<int>(world_scenarios.size()), num_threads, seed,
                         SourcesOf<TrainingScenarioGenerator>(world_scenarios)) {}

BatchedEnvironment::BatchedEnvironment(const EnvironmentConfig& config,
                                       const std::vector<Scenario>& scenarios, int num_threads)
    : BatchedEnvironment(config, static_cast<int>(scenarios.size()), num_threads, 0,
                         SourcesOf<FixedScenarioSource>(scenarios)) {}

BatchedEnvironment::BatchedEnvironment(
    const EnvironmentConfig& config, int num_envs, int num_threads, std::uint64_t seed,
    const std::vector<std::shared_ptr<const ScenarioSource>>& sources)
    : OwnedStepResults(num_envs, ObservationSize(config)),
      num_envs_(num_envs),
      observation_size_(ObservationSize(config)),
      seed_(seed),
      histories_(num_envs),
      pool_(std::make_unique<ThreadPool>(std::min(num_threads, num_envs))),
      step_order_(num_envs),
      step_cost_(num_envs, 0) {
  std::iota(step_order_.begin(), step_order_.end(), 0);
  for (const auto& source : sources) {
    worlds_.push_back(std::make_unique<Environment>(config, source));
    next_episodes_.push_back(std::make_unique<NextEpisode>());
    next_episodes_.back()->environment = std::make_unique<Environment>(config, source);
    next_episodes_.back()->observation.resize(observation_size_);
  }
}

BatchedEnvironment::~BatchedEnvironment() = default;

std::uint64_t TrainingEpisodeSeed(std::uint64_t seed, int world, std::uint64_t episode) {
  return DeriveSeed(seed, "episode", (static_cast<std::uint64_t>(world) << 32U) + episode);
}

std::uint64_t TestScenarioSeed(std::uint64_t master_seed, std::uint64_t k) {
  return DeriveSeed(master_seed, "test-scenario", k);
}

void BatchedEnvironment::Reset(std::optional<std::uint64_t> seed) { Reset(seed, OwnOutputs()); }

void BatchedEnvironment::Reset(std::optional<std::uint64_t> seed, const BatchedOutputs& outputs) {
  ChooseResetEpisodes(seed);
  pool_->ParallelFor(num_envs_, [this, &outputs](int i) { ResetWorld(i, outputs); });
}

void BatchedEnvironment::ChooseResetEpisodes(std::optional<std::uint64_t> seed) {
  if (seed) {
    seed_ = *seed;
    for (WorldHistory& history : histories_) history.episode = 0;
  } else if (started_) {
    for (WorldHistory& history : histories_) ++history.episode;
  }
  started_ = true;
}

void BatchedEnvironment::ResetWorld(int world) { ResetWorld(world, OwnOutputs()); }

void BatchedEnvironment::ResetWorld(int world, const BatchedOutputs& outputs) {
  StartEpisode(world, &outputs.observations[static_cast<std::size_t>(world) * observation_size_]);
  WriteCriticObservation(world, critic_observations_);
  outputs.terminated[world] = outputs.truncated[world] = 0;
  outputs.rewards[world] = 0.0f;
  finished_episodes_[world].reset();
}

void BatchedEnvironment::ObserveVesselsForCritic(int vessels) {
  critic_vessels_ = vessels;
  const std::size_t size = static_cast<std::size_t>(num_envs_) * critic_observation_size();
  critic_observations_.assign(size, 0.0f);
  final_critic_observations_.assign(size, 0.0f);
}

void BatchedEnvironment::WriteCriticObservation(int world, std::vector<float>& rows) const {
  if (critic_vessels_ == 0) return;
  colav::WriteCriticObservation(
      worlds_[world]->world(), critic_vessels_,
      rows.data() + static_cast<std::ptrdiff_t>(world) * critic_observation_size());
}

void BatchedEnvironment::StepWorld(int world, const double* action) {
  StepWorld(world, action, OwnOutputs());
}

void BatchedEnvironment::Step(const float* actions) { StepAll(actions, OwnOutputs()); }

void BatchedEnvironment::Step(const float* actions, const BatchedOutputs& outputs) {
  StepAll(actions, outputs);
}

void BatchedEnvironment::Step(const double* actions, const BatchedOutputs& outputs) {
  StepAll(actions, outputs);
}

template <typename Action>
void BatchedEnvironment::StepAll(const Action* actions, const BatchedOutputs& outputs) {
  const auto step = [this, actions, &outputs](int world) {
    StepWorld(world, actions + static_cast<std::ptrdiff_t>(world) * kActionSize, outputs);
  };
  if (pool_->num_threads() == 1) {  // one share: nothing to order, no clock to read
    for (int world = 0; world < num_envs_; ++world) step(world);
    return;
  }
  pool_->ParallelFor(num_envs_, [this, &step](int i) {
    const int world = step_order_[i];
    const std::uint64_t start = Ticks();
    step(world);
    step_cost_[world] = Ticks() - start;
  });
  OrderSharesByCost();
}

void BatchedEnvironment::OrderSharesByCost() {
  const int threads = pool_->num_threads();
  for (int p = 0; p < threads; ++p) {
    std::sort(step_order_.begin() + ThreadPool::ShareStart(num_envs_, threads, p),
              step_order_.begin() + ThreadPool::ShareStart(num_envs_, threads, p + 1),
              [this](int a, int b) { return step_cost_[a] > step_cost_[b]; });
  }
}

template <typename Action>
void BatchedEnvironment::StepWorld(int world, const Action* action, const BatchedOutputs& outputs) {
  const std::size_t row = static_cast<std::size_t>(world) * observation_size_;
  float* observation = &outputs.observations[row];
  const double clipped[kActionSize] = {std::clamp<double>(action[0], -1.0, 1.0),
                                       std::clamp<double>(action[1], -1.0, 1.0)};
  std::vector<double>& played = histories_[world].actions;
  played.insert(played.end(), clipped, clipped + kActionSize);
  const StepResult result = worlds_[world]->Step(clipped, observation);
  outputs.rewards[world] = static_cast<float>(result.reward);
  outputs.terminated[world] = result.terminated;
  outputs.truncated[world] = result.truncated;
  finished_episodes_[world] = result.episode;
  if (result.terminated || result.truncated) {
    std::copy(observation, observation + observation_size_, &outputs.final_observations[row]);
    WriteCriticObservation(world, final_critic_observations_);
    ++histories_[world].episode;
    StartEpisode(world, observation);
  }
  WriteCriticObservation(world, critic_observations_);
}

void BatchedEnvironment::Restore(const std::vector<WorldHistory>& histories) {
  if (static_cast<int>(histories.size()) != num_envs_) {
    throw std::invalid_argument("histories of " + std::to_string(histories.size()) +
                                " worlds for an environment of " + std::to_string(num_envs_));
  }
  started_ = true;
  std::vector<std::string> errors(num_envs_);
  pool_->ParallelFor(num_envs_, [&](int i) {
    try {
      ReplayWorld(i, histories[i]);
    } catch (const std::invalid_argument& error) {
      errors[i] = error.what();
    }
  });
  for (const std::string& error : errors) {
    if (!error.empty()) throw std::invalid_argument(error);
  }
}

void BatchedEnvironment::ReplayWorld(int world, const WorldHistory& history) {
  const std::vector<double>& actions = history.actions;
  const bool valid = actions.size() % kActionSize == 0 &&
                     std::all_of(actions.begin(), actions.end(),
                                 [](double a) { return a >= -1.0 && a <= 1.0; });  // NaN fails
  if (!valid) {
    throw std::invalid_argument("world " + std::to_string(world) +
                                ": recorded actions that no step applies");
  }
  float* observation =
      OwnOutputs().observations + static_cast<std::ptrdiff_t>(world) * observation_size_;
  histories_[world].episode = history.episode;
  StartEpisode(world, observation);
  for (std::size_t k = 0; k < actions.size(); k += kActionSize) {
    const StepResult result = worlds_[world]->Step(&actions[k], observation);
    if (result.terminated || result.truncated) {
      throw std::invalid_argument("world " + std::to_string(world) + ": its episode ends after " +
                                  std::to_string(k / kActionSize + 1) + " of " +
                                  std::to_string(actions.size() / kActionSize) +
                                  " recorded actions");
    }
  }
  histories_[world].actions = actions;
  WriteCriticObservation(world, critic_observations_);
}

std::uint64_t BatchedEnvironment::EpisodeSeed(int world, std::uint64_t episode) const {
  return TrainingEpisodeSeed(seed_, world, episode);
}

void BatchedEnvironment::StartEpisode(int world, float* observation) {
  histories_[world].actions.clear();
  if (!TakeNextEpisode(world, observation)) {
    worlds_[world]->Reset(EpisodeSeed(world, histories_[world].episode), observation);
  }
  PrepareNextEpisode(world);
}

bool BatchedEnvironment::TakeNextEpisode(int world, float* observation) {
  NextEpisode& next = *next_episodes_[world];
  int state = next.state.load(std::memory_order_acquire);
  if (state == NextEpisode::kQueued &&
      next.state.compare_exchange_strong(state, NextEpisode::kEmpty, std::memory_order_acquire)) {
    return false;  // not started yet: cancelled, its task will find nothing to do
  }
  while (state == NextEpisode::kBuilding) {  // a worker is at it: it ends sooner than a reset
    std::this_thread::yield();
    state = next.state.load(std::memory_order_acquire);
  }
  next.state.store(NextEpisode::kEmpty, std::memory_order_relaxed);
  if (state != NextEpisode::kReady || next.seed != EpisodeSeed(world, histories_[world].episode)) {
    return false;  // none, or one of a seed given to Reset since
  }
  std::swap(worlds_[world], next.environment);
  std::copy(next.observation.begin(), next.observation.end(), observation);
  return true;
}

void BatchedEnvironment::PrepareNextEpisodesWith(std::function<void(int world)> schedule) {
  schedule_preparation_ = std::move(schedule);
}

void BatchedEnvironment::PrepareNextEpisode(int world) {
  if (!schedule_preparation_ && pool_->num_threads() == 1) return;  // no worker to prepare it
  NextEpisode& next = *next_episodes_[world];
  next.seed = EpisodeSeed(world, histories_[world].episode + 1);
  next.state.store(NextEpisode::kQueued, std::memory_order_release);
  if (schedule_preparation_) {
    schedule_preparation_(world);
  } else {
    pool_->RunWhenIdle([this, world] { BuildNextEpisode(world); });
  }
}

void BatchedEnvironment::BuildNextEpisode(int world) {
  NextEpisode& next = *next_episodes_[world];
  int queued = NextEpisode::kQueued;
  if (!next.state.compare_exchange_strong(queued, NextEpisode::kBuilding,
                                          std::memory_order_acquire)) {
    return;  // cancelled, or built by an earlier task of the same world
  }
  try {
    next.environment->Reset(next.seed, next.observation.data());
    next.state.store(NextEpisode::kReady, std::memory_order_release);
  } catch (...) {
    // The world then resets itself and meets the error in the step, where it is reported.
    next.state.store(NextEpisode::kEmpty, std::memory_order_release);
  }
}

}  // namespace colav

#include "env/batched_environment.h"

#include <algorithm>

#include "env/environment.h"
#include "env/training_scenario.h"
#include "src/seeding.h"
#include "src/threads/thread_pool.h"

namespace colav {

BatchedEnvironment::BatchedEnvironment(const EnvironmentConfig& config, int num_envs,
                                       int num_threads, std::uint64_t seed)
    : num_envs_(num_envs),
      seed_(seed),
      episode_counts_(num_envs, 0),
      pool_(std::make_unique<ThreadPool>(std::min(num_threads, num_envs))),
      observations_(static_cast<std::size_t>(num_envs) * kObservationSize, 0.0f),
      final_observations_(observations_.size(), 0.0f),
      rewards_(num_envs, 0.0f),
      terminated_(num_envs, 0),
      truncated_(num_envs, 0),
      finished_episodes_(num_envs) {
  const auto source = std::make_shared<TrainingScenarioGenerator>();
  for (int i = 0; i < num_envs; ++i) {
    worlds_.push_back(std::make_unique<Environment>(config, source));
  }
}

BatchedEnvironment::~BatchedEnvironment() = default;

std::uint64_t TrainingEpisodeSeed(std::uint64_t seed, int world, std::uint64_t episode) {
  return DeriveSeed(seed, "episode", (static_cast<std::uint64_t>(world) << 32U) + episode);
}

void BatchedEnvironment::Reset() {
  pool_->ParallelFor(num_envs_, [this](int i) {
    worlds_[i]->Reset(TrainingEpisodeSeed(seed_, i, episode_counts_[i]),
                      &observations_[static_cast<std::size_t>(i) * kObservationSize]);
    terminated_[i] = truncated_[i] = 0;
    rewards_[i] = 0.0f;
    finished_episodes_[i].reset();
  });
}

void BatchedEnvironment::Step(const float* actions) {
  pool_->ParallelFor(num_envs_,
                     [this, actions](int i) { StepWorld(i, actions + i * kActionSize); });
}

void BatchedEnvironment::StepWorld(int i, const float* action) {
  float* observation = &observations_[static_cast<std::size_t>(i) * kObservationSize];
  const double clipped[kActionSize] = {std::clamp<double>(action[0], -1.0, 1.0),
                                       std::clamp<double>(action[1], -1.0, 1.0)};
  const StepResult result = worlds_[i]->Step(clipped, observation);
  rewards_[i] = static_cast<float>(result.reward);
  terminated_[i] = result.terminated;
  truncated_[i] = result.truncated;
  finished_episodes_[i] = result.episode;
  if (result.terminated || result.truncated) {
    std::copy(observation, observation + kObservationSize,
              &final_observations_[static_cast<std::size_t>(i) * kObservationSize]);
    ++episode_counts_[i];
    worlds_[i]->Reset(TrainingEpisodeSeed(seed_, i, episode_counts_[i]), observation);
  }
}

}  // namespace colav

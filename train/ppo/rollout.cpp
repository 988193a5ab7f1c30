#include "train/ppo/rollout.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "train/ppo/normal_log_density.h"

namespace colav {

bool BootstrapsFromFinalObservation(bool terminated, bool truncated, bool timeouts_terminal) {
  return truncated && !terminated && !timeouts_terminal;
}

RolloutCollector::RolloutCollector(const EnvironmentConfig& config,
                                   const std::vector<TrainingScenarioConfig>& world_scenarios,
                                   int threads, std::uint64_t env_seed, const RolloutRules& rules)
    : config_(config),
      threads_(threads),
      env_seed_(env_seed),
      rules_(rules),
      env_(std::make_unique<BatchedEnvironment>(config, world_scenarios, threads, env_seed)),
      reward_scaler_(env_->num_envs(), rules.gamma),
      normalized_observations_(rules.normalize_navigation
                                   ? static_cast<std::size_t>(env_->num_envs()) *
                                         env_->observation_size()
                                   : 0),
      final_observation_(env_->observation_size()),
      mean_(static_cast<std::size_t>(env_->num_envs()) * kActionSize),
      bounded_actions_(mean_.size()),
      scratch_values_(env_->num_envs()),
      scratch_means_(kActionSize) {
  env_->ObserveVesselsForCritic(rules.critic_vessels);
  env_->Reset();
  SeeObservations(true);
}

void RolloutCollector::ReplaceWorlds(const std::vector<TrainingScenarioConfig>& world_scenarios) {
  std::vector<WorldHistory> next_episodes = env_->histories();
  for (WorldHistory& history : next_episodes) {
    ++history.episode;
    history.actions.clear();
  }
  env_ = std::make_unique<BatchedEnvironment>(config_, world_scenarios, threads_, env_seed_);
  env_->ObserveVesselsForCritic(rules_.critic_vessels);
  env_->Restore(next_episodes);
  reward_scaler_.RestartReturns();
  std::fill(states_.begin(), states_.end(), 0.0f);  // every world starts an episode
  SeeObservations(true);
}

void RolloutCollector::SeeObservations(bool new_observations) {
  if (!rules_.normalize_navigation) return;
  const int N = env_->num_envs();
  std::copy_n(env_->observations(), normalized_observations_.size(),
              normalized_observations_.data());
  float* seen = normalized_observations_.data();
  if (new_observations) navigation_normalizer_.Update(seen, N, env_->observation_size());
  navigation_normalizer_.Normalize(seen, N, env_->observation_size());
}

const float* RolloutCollector::SeenObservations() const {
  return rules_.normalize_navigation ? normalized_observations_.data() : env_->observations();
}

void RolloutCollector::RestoreWorlds(const std::vector<WorldHistory>& histories) {
  env_->Restore(histories);
  SeeObservations(false);
}

void RolloutCollector::RestoreNavigationMoments(const NavigationNormalizer::Moments& moments) {
  navigation_normalizer_.Restore(moments);
  SeeObservations(false);
}

std::optional<NavigationNormalization> RolloutCollector::navigation_normalization() const {
  if (!rules_.normalize_navigation) return std::nullopt;
  return navigation_normalizer_.Normalization();
}

bool RolloutCollector::Collect(FastActorCritic& policy, const torch::Tensor& noise,
                               RolloutBuffer& buffer, const StepCallback& after_step) {
  const int N = env_->num_envs();
  const float* log_std = policy.log_std();
  float std[kActionSize];
  double log_prob_constant = -kActionSize * kLogSqrtTwoPi;
  for (int j = 0; j < kActionSize; ++j) {
    std[j] = std::exp(log_std[j]);
    log_prob_constant -= log_std[j];
  }
  const float* epsilon = noise.data_ptr<float>();
  const bool squash = policy.squash_actions();
  const int state_size = policy.state_size();
  if (states_.size() != static_cast<std::size_t>(N) * state_size) {
    states_.assign(N * state_size, 0.0f);
  }
  float* states = state_size > 0 ? states_.data() : nullptr;
  const int critic_size = env_->critic_observation_size();
  for (int t = 0; t < buffer.num_steps(); ++t) {
    float* observations = buffer.observations(t);
    std::copy_n(SeenObservations(), N * env_->observation_size(), observations);
    std::copy(states_.begin(), states_.end(), buffer.states(t));
    float* critic_observations = critic_size > 0 ? buffer.critic_observations(t) : nullptr;
    if (critic_observations) {
      std::copy_n(env_->critic_observations(), N * critic_size, critic_observations);
    }
    policy.Predict(observations, N, mean_.data(), buffer.values(t), states, critic_observations);
    float* actions = buffer.actions(t);
    for (int e = 0; e < N; ++e) {
      // log N(a; mean, std) with a = mean + std * eps only depends on eps.
      double log_prob = log_prob_constant;
      for (int j = 0; j < kActionSize; ++j) {
        const int k = e * kActionSize + j;
        const float eps = epsilon[(t * N) * kActionSize + k];
        actions[k] = mean_[k] + std[j] * eps;
        bounded_actions_[k] = BoundedAction(actions[k], squash);
        log_prob -= 0.5 * static_cast<double>(eps) * eps;
      }
      buffer.log_probs(t)[e] = static_cast<float>(log_prob);
    }
    const auto step_start = std::chrono::steady_clock::now();
    env_->Step(bounded_actions_.data());
    env_seconds_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - step_start).count();
    SeeObservations(true);

    finished_.clear();
    for (int e = 0; e < N; ++e) {
      buffer.dones(t)[e] = env_->terminated()[e] || env_->truncated()[e];
      buffer.bootstrapped(t)[e] = BootstrapsFromFinalObservation(
          env_->terminated()[e] != 0, env_->truncated()[e] != 0, rules_.timeouts_terminal);
      if (const auto& episode = env_->finished_episodes()[e]) {
        // The world has moved on to its next episode already.
        const std::uint64_t index = env_->histories()[e].episode - 1;
        finished_.push_back({e, TrainingEpisodeSeed(env_seed_, e, index), *episode});
      }
    }
    if (rules_.scale_rewards) {
      reward_scaler_.Scale(env_->rewards(), buffer.dones(t), buffer.rewards(t));
    } else {
      std::copy_n(env_->rewards(), N, buffer.rewards(t));
    }
    ValueFinalObservations(policy, t, buffer);
    for (int e = 0; e < N; ++e) {
      if (buffer.dones(t)[e] != 0) std::fill_n(states_.begin() + e * state_size, state_size, 0.0f);
    }
    if (!after_step(finished_)) return false;
  }
  scratch_states_ = states_;  // the next rollout starts from states_ again
  policy.Predict(SeenObservations(), N, mean_.data(), buffer.last_values(),
                 state_size > 0 ? scratch_states_.data() : nullptr,
                 critic_size > 0 ? env_->critic_observations() : nullptr);
  return true;
}

void RolloutCollector::ValueFinalObservations(FastActorCritic& policy, int t,
                                              RolloutBuffer& buffer) {
  const int N = env_->num_envs();
  for (int e = 0; e < N; ++e) {
    buffer.final_values(t)[e] = 0.0f;
    if (buffer.bootstrapped(t)[e] == 0) continue;
    // Rare (one step in 2000 per world): value the one row on its own.
    std::copy_n(
        env_->final_observations() + static_cast<std::ptrdiff_t>(e) * env_->observation_size(),
        env_->observation_size(), final_observation_.data());
    if (rules_.normalize_navigation) {
      navigation_normalizer_.Normalize(final_observation_.data(), 1, env_->observation_size());
    }
    // From the state the episode's last step left (a copy: the world starts afresh).
    const int state_size = policy.state_size();
    scratch_states_.assign(states_.begin() + e * state_size,
                           states_.begin() + (e + 1) * state_size);
    const int critic_size = env_->critic_observation_size();
    policy.Predict(final_observation_.data(), 1, scratch_means_.data(), scratch_values_.data(),
                   state_size > 0 ? scratch_states_.data() : nullptr,
                   critic_size > 0 ? env_->final_critic_observations() +
                                         static_cast<std::ptrdiff_t>(e) * critic_size
                                   : nullptr);
    buffer.final_values(t)[e] = scratch_values_[0];
  }
}

}  // namespace colav

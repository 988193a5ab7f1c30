#include "train/ppo/update.h"

#include <algorithm>
#include <cmath>

#include "models/actor_critic_kernels.h"
#include "train/ppo/sequence_minibatches.h"

namespace colav {

PpoUpdater::PpoUpdater(ActorCritic model, const PpoOptions& options)
    : options_(options),
      policy_(model, std::max(options.batch_size, options.n_envs)),
      log_std_(model->log_std()),
      optimizer_(model->TrainableParameters(), options.adam),
      rows_(options.batch_size),
      critic_rows_(options.batch_size),
      actions_(static_cast<std::size_t>(options.batch_size) * kActionSize),
      old_log_probs_(options.batch_size),
      advantages_(options.batch_size),
      returns_(options.batch_size),
      d_mean_(static_cast<std::size_t>(options.batch_size) * kActionSize),
      d_value_(options.batch_size) {
  // The model decides the action distribution, and with it the entropy the bonus rewards.
  options_.loss.squashed_actions = policy_.squash_actions();
  const std::vector<torch::Tensor> critic = model->CriticParameters();
  for (std::size_t i = 0; i < policy_.parameters().size(); ++i) {
    const bool critics = std::any_of(critic.begin(), critic.end(), [&](const torch::Tensor& p) {
      return p.is_same(policy_.parameters()[i]);
    });
    if (!critics) actor_gradients_.push_back(policy_.gradients()[i]);
  }
  BoundStd();
}

void PpoUpdater::BoundStd() {
  if (options_.std_max <= 0.0) return;
  const float largest = static_cast<float>(std::log(options_.std_max));
  float* log_std = log_std_.data_ptr<float>();
  for (int j = 0; j < kActionSize; ++j) log_std[j] = std::min(log_std[j], largest);
}

void PpoUpdater::ZeroActorGradients() {
  for (const torch::Tensor& gradient : actor_gradients_) gradient.zero_();
}

PpoMinibatch PpoUpdater::Gather(const RolloutBuffer& buffer, const std::int64_t* indices, int B) {
  const bool frozen_features = !policy_.extractor_trainable();
  const int width = frozen_features ? policy_.features_dim() : buffer.observation_size();
  const float* source = frozen_features ? features_.data() : buffer.observations().data();
  const int critic_size = buffer.critic_observation_size();
  for (int b = 0; b < B; ++b) {
    const std::int64_t i = indices[b];
    rows_[b] = source + i * width;
    std::copy_n(&buffer.actions()[i * kActionSize], kActionSize, &actions_[b * kActionSize]);
    if (critic_size > 0) critic_rows_[b] = buffer.critic_observations().data() + i * critic_size;
    old_log_probs_[b] = buffer.log_probs()[i];
    advantages_[b] = buffer.advantages()[i];
    returns_[b] = buffer.returns()[i];
  }
  return {B, actions_.data(), old_log_probs_.data(), advantages_.data(), returns_.data()};
}

const std::int64_t* PpoUpdater::EpochOrder(const RolloutBuffer& buffer,
                                           torch::Generator& generator) {
  if (policy_.recurrent_size() > 0) {
    epoch_order_ = SequenceMinibatchOrder(buffer.num_steps(), buffer.num_envs(),
                                          options_.sequence_length, options_.batch_size, generator);
  } else {
    const torch::Tensor permutation = torch::randperm(buffer.size(), generator, torch::kLong);
    const std::int64_t* samples = permutation.data_ptr<std::int64_t>();
    epoch_order_.assign(samples, samples + buffer.size());
  }
  return epoch_order_.data();
}

void PpoUpdater::SetSequences(const RolloutBuffer& buffer, const std::int64_t* indices, int B) {
  const int S = B / options_.sequence_length;
  initial_states_.resize(S);
  for (int s = 0; s < S; ++s) {
    initial_states_[s] = buffer.states().data() + indices[s] * buffer.state_size();
  }
  EpisodeStartsInSequences(buffer, indices, B, options_.sequence_length, resets_);
  policy_.SetSequences(initial_states_.data(), resets_.data(), S);
}

UpdateStats PpoUpdater::Update(const RolloutBuffer& buffer, torch::Generator& generator) {
  const int n = buffer.size();
  if (!policy_.extractor_trainable()) {
    // A frozen extractor maps each observation to fixed features: encode the rollout once.
    features_.resize(static_cast<std::size_t>(n) * policy_.features_dim());
    policy_.Features(buffer.observations().data(), n, features_.data());
  }
  UpdateStats stats;
  int minibatches = 0;
  float d_log_std[kActionSize];
  for (int epoch = 0; epoch < options_.n_epochs; ++epoch) {
    const bool recurrent = policy_.recurrent_size() > 0;
    const std::int64_t* order = EpochOrder(buffer, generator);
    double epoch_kl = 0.0;
    int epoch_minibatches = 0;
    for (int start = 0; start < n; start += options_.batch_size) {
      const int B = std::min(options_.batch_size, n - start);
      const PpoMinibatch batch = Gather(buffer, order + start, B);
      if (recurrent) SetSequences(buffer, order + start, B);
      if (buffer.critic_observation_size() > 0) policy_.SetCriticObservations(critic_rows_.data());
      if (policy_.extractor_trainable()) {
        policy_.ForwardObservations(rows_.data(), B);
      } else {
        policy_.ForwardFeatures(rows_.data(), B);
      }
      const PpoLossStats loss =
          PpoLossGradients(policy_.mean(), policy_.log_std(), policy_.value(), batch, options_.loss,
                           d_mean_.data(), d_log_std, d_value_.data());
      if (!std::isfinite(loss.loss)) {
        throw TrainingDiverged("non-finite loss (policy " +
                               std::to_string(loss.policy_gradient_loss) + ", value " +
                               std::to_string(loss.value_loss) + ") in update " +
                               std::to_string(n_updates_ + epoch + 1));
      }
      policy_.Backward(d_mean_.data(), d_value_.data(), d_log_std, B);
      if (actor_held_) ZeroActorGradients();
      const double norm = GradientNorm(policy_.gradients());
      optimizer_.Step(policy_.gradients(), ClipCoefficient(norm, options_.max_grad_norm));
      BoundStd();

      stats.policy_gradient_loss += loss.policy_gradient_loss;
      stats.value_loss += loss.value_loss;
      stats.entropy_loss += loss.entropy_loss;
      stats.clip_fraction += loss.clip_fraction;
      stats.loss = loss.loss;
      epoch_kl += loss.approx_kl;
      ++epoch_minibatches;
      ++minibatches;
    }
    stats.approx_kl = epoch_kl / epoch_minibatches;
  }
  CheckParametersFinite();
  n_updates_ += options_.n_epochs;
  stats.policy_gradient_loss /= minibatches;
  stats.value_loss /= minibatches;
  stats.entropy_loss /= minibatches;
  stats.clip_fraction /= minibatches;
  stats.explained_variance = buffer.ExplainedVariance();
  for (int j = 0; j < kActionSize; ++j) stats.std += std::exp(policy_.log_std()[j]) / kActionSize;
  stats.n_updates = n_updates_;
  return stats;
}

void PpoUpdater::CheckParametersFinite() const {
  for (const torch::Tensor& parameter : policy_.parameters()) {
    if (!kernels::AllFinite(parameter.data_ptr<float>(), static_cast<int>(parameter.numel()))) {
      throw TrainingDiverged("non-finite parameter after update " +
                             std::to_string(n_updates_ + options_.n_epochs));
    }
  }
}

}  // namespace colav

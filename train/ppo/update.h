// The PPO update of one rollout (SB3 PPO.train, reference-learning 6.4): n_epochs passes over the
// rollout in shuffled minibatches; per minibatch the clipped-surrogate loss, its gradients through
// the hand-written backward pass, global gradient-norm clipping and one Adam step over the
// trainable parameters. A recurrent policy's minibatches are whole sequences of consecutive steps
// (sequence_minibatches.h), each starting from the state the rollout recorded.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/actor_critic_fast.h"
#include "models/adam.h"
#include "src/training_diverged.h"
#include "train/ppo/config.h"
#include "train/ppo/rollout_buffer.h"

namespace colav {

/// What SB3 logs after an update (its train/* names).
struct UpdateStats {
  double policy_gradient_loss = 0.0;  ///< mean over all minibatches
  double value_loss = 0.0;
  double entropy_loss = 0.0;
  double approx_kl = 0.0;  ///< mean over the last epoch's minibatches
  double clip_fraction = 0.0;
  double loss = 0.0;  ///< of the last minibatch
  double explained_variance = 0.0;
  double std = 0.0;            ///< mean of exp(log_std) after the update
  std::int64_t n_updates = 0;  ///< epochs run so far (SB3 counts epochs)
};

class PpoUpdater {
 public:
  PpoUpdater(ActorCritic model, const PpoOptions& options);

  /// Trains on `buffer` (returns and advantages computed), shuffling with `generator`. Throws
  /// TrainingDiverged on a non-finite loss or parameter.
  UpdateStats Update(const RolloutBuffer& buffer, torch::Generator& generator);

  /// While held (a critic warm-up, critic_warmup.h), updates train only the critic's own
  /// parameters (ActorCritic::CriticParameters): the others' gradients are zeroed, so Adam, whose
  /// moments for them are then 0, leaves them bit for bit, and the gradient norm clipped is the
  /// critic's.
  void set_actor_held(bool held) { actor_held_ = held; }
  /// A fresh Adam over the same parameters (moments 0, step count 0), at the same options.
  void RestartOptimizer() { optimizer_ = Adam(policy_.parameters(), options_.adam); }

  FastActorCritic& policy() { return policy_; }
  Adam& optimizer() { return optimizer_; }
  std::int64_t n_updates() const { return n_updates_; }
  void set_n_updates(std::int64_t n_updates) { n_updates_ = n_updates; }

 private:
  /// Points rows_ (and critic_rows_ for a privileged critic) at the samples `indices` and copies
  /// their loss inputs.
  PpoMinibatch Gather(const RolloutBuffer& buffer, const std::int64_t* indices, int B);
  /// The epoch's order of the samples, minibatch after minibatch: shuffled samples, or for a
  /// recurrent policy shuffled whole sequences (sequence_minibatches.h).
  const std::int64_t* EpochOrder(const RolloutBuffer& buffer, torch::Generator& generator);
  /// A recurrent policy's minibatch of `indices` (sequence_minibatches.h): the initial states and
  /// the episode starts of its sequences.
  void SetSequences(const RolloutBuffer& buffer, const std::int64_t* indices, int B);
  void CheckParametersFinite() const;
  /// Clamps the log std to log(options_.std_max), if set.
  void BoundStd();
  void ZeroActorGradients();

  PpoOptions options_;
  FastActorCritic policy_;
  torch::Tensor log_std_;  ///< the model's, shared
  Adam optimizer_;
  std::int64_t n_updates_ = 0;
  bool actor_held_ = false;
  std::vector<torch::Tensor> actor_gradients_;  ///< of every trainable parameter not the critic's
  std::vector<float> features_;  // [rollout, features_dim] when the extractor is frozen
  std::vector<const float*> rows_;
  std::vector<const float*> critic_rows_;  // a privileged critic's observation rows
  std::vector<float> actions_, old_log_probs_, advantages_, returns_;
  std::vector<float> d_mean_, d_value_;
  std::vector<std::int64_t> epoch_order_;
  std::vector<const float*> initial_states_;
  std::vector<std::uint8_t> resets_;
};

}  // namespace colav

// The configuration of a PPO run: keys, defaults (the paper's table, reference-learning 6.4) and
// their translation into the trainer's and the model's options. configs/ppo.yaml lists them all.
#pragma once

#include <cstdint>

#include "models/actor_critic.h"
#include "src/config.h"
#include "train/ppo/loss.h"
#include "train/ppo/optimizer.h"

namespace colav {

struct PpoOptions {
  std::int64_t total_steps = 3'000'000;
  int n_envs = 8;
  int n_steps = 1024;  ///< per environment and rollout
  int batch_size = 32;
  int n_epochs = 4;
  double gamma = 0.999;
  double gae_lambda = 0.98;
  double max_grad_norm = 0.5;
  PpoLossOptions loss;
  AdamOptions adam;
  std::int64_t checkpoint_interval = 30'000;  ///< steps between checkpoints
  bool keep_checkpoints = true;               ///< also keep checkpoints/policy_<step>.pt
  std::uint64_t seed = 0;
  int env_threads = 0;  ///< 0: one per core
};

/// Declares ppo.*, extractor.*, train.* and env.* keys.
void AddPpoKeys(ConfigSchema& schema);
PpoOptions PpoOptionsFrom(const Config& config);
/// The actor-critic of a configuration (extractor, hidden sizes, log std, seed).
ActorCriticOptions ActorCriticOptionsFrom(const Config& config);

}  // namespace colav

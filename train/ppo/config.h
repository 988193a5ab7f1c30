// The configuration of a PPO run: its options (defaults: the paper's table, reference-learning
// 6.4) and the configuration keys bound to them. configs/ppo.yaml lists them all.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "env/environment_spec.h"
#include "env/training_scenario.h"
#include "models/actor_critic.h"
#include "models/adam.h"
#include "src/options_binding.h"
#include "train/ppo/learning_rate_schedule.h"
#include "train/ppo/loss.h"

namespace colav {

struct PpoOptions {
  std::int64_t total_steps = 3'000'000;
  int n_envs = 8;
  int n_steps = 1024;  ///< per environment and rollout
  int batch_size = 32;
  int n_epochs = 4;
  /// Recurrent policies (policy.recurrent_size > 0): each minibatch is batch_size /
  /// sequence_length sequences of this many consecutive steps of one world, backpropagated
  /// through their steps from the state the rollout recorded at their first.
  int sequence_length = 16;
  double gamma = 0.999;
  double gae_lambda = 0.98;
  double max_grad_norm = 0.5;
  /// The action distribution's largest std: the log std is clamped to log(std_max) when the
  /// updater starts and after each Adam step, so that the entropy bonus cannot widen the clipped
  /// Gaussian far past the action box (best's std grows to 64-124). 0: unbounded (SB3's).
  double std_max = 0.0;
  /// Time-outs end the return like a terminal state (the reference's training) instead of being
  /// bootstrapped with gamma * V(final observation) (Stable-Baselines3's rule).
  bool timeouts_terminal = false;
  /// Scale the rewards the learner sees by the running spread of the discounted return
  /// (reward_scaling.h; SB3's VecNormalize norm_reward). Off in the paper's recipe.
  bool normalize_reward = false;
  /// Normalise the navigation values the policy sees by their running mean and spread
  /// (navigation_normalizer.h; SB3's VecNormalize norm_obs, without clipping, on the navigation
  /// values only). The exported policy applies the same map. Off in the paper's recipe.
  bool normalize_navigation = false;
  PpoLossOptions loss;
  AdamOptions adam;
  /// How adam.learning_rate moves over the run.
  LearningRateSchedule learning_rate_schedule = LearningRateSchedule::kConstant;
  /// The updates of rollouts ending at or before this step train the critic alone, the actor
  /// held (critic_warmup.h): for a run that starts from a trained policy. 0: none (the paper's).
  std::int64_t critic_warmup_steps = 0;
  std::int64_t checkpoint_interval = 30'000;  ///< steps between checkpoints
  bool keep_checkpoints = true;               ///< also keep checkpoints/policy_<step>.pt
  std::uint64_t seed = 0;
  int env_threads = 0;  ///< 0: one per core
};

/// The environment defaults with log closeness (reference-simulator, the sensor's transform).
EnvironmentConfig AuthorsTrainingEnvironment();

/// Everything a train_ppo run is configured with.
struct PpoRunOptions {
  PpoOptions ppo;
  /// Its seed follows from ppo.seed.
  ActorCriticOptions model;
  /// A policy.pt (train_ppo's, or a student of distill_policy.py) whose weights the run starts
  /// from instead of its own initialisation; empty: none. Adam's moments and every running
  /// statistic still start afresh.
  std::filesystem::path init_policy;
  /// With init_policy: keep its log std (true), or start from model.log_std_init (false), e.g. a
  /// narrower distribution, so that the policy PPO trains acts nearer the deterministic one tested.
  bool init_keeps_log_std = true;
  /// Log closeness, as in the authors' environment code: the ablation (studies/ablation.yaml)
  /// found it is what their agents were trained with, and what closes the gap to them.
  EnvironmentConfig env = AuthorsTrainingEnvironment();
  /// The closeness transform a VAE extractor's encoder must record (empty: env.closeness). The
  /// paper recipe feeds the environment's log closeness to an encoder trained on the paper's
  /// linear closeness, as the authors' code did, so linear is expected by default.
  std::optional<ClosenessTransform> encoder_closeness = ClosenessTransform::kLinear;
  /// The worlds the agent trains in; the paper's by default. Evaluation always uses the paper's.
  TrainingScenarioConfig worlds;
  /// A second kind of training world, for a mix: this share of the ppo.n_envs worlds (rounded to
  /// whole worlds, the last ones) play it instead of `worlds`.
  TrainingScenarioConfig second_worlds;
  double second_worlds_share = 0.0;
  /// For a curriculum: those worlds play `worlds` until the first rollout that starts at or after
  /// this step, then `second_worlds`. A step rather than a share of ppo.total_steps, so that
  /// extending a run does not move it.
  std::int64_t second_worlds_from_step = 0;
};

/// The training scenario of each of the run's ppo.n_envs worlds in a rollout that starts at
/// `step`: `worlds`, then the round(second_worlds_share * n_envs) worlds of `second_worlds` once
/// `step` reaches second_worlds_from_step (before, those play `worlds` too).
std::vector<TrainingScenarioConfig> WorldScenarios(const PpoRunOptions& options, std::int64_t step);

/// The ppo.*, policy.*, extractor.*, train.*, env.*, world.* and world2.* keys. Reading checks that
/// a VAE extractor has an encoder file and derives the model's seed from train.seed.
OptionsBinding<PpoRunOptions> PpoRunBinding();

}  // namespace colav

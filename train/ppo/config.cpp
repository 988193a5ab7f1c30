#include "train/ppo/config.h"

#include <sstream>
#include <string>

#include "env/environment_config.h"
#include "src/error.h"
#include "src/seeding.h"

namespace colav {
namespace {

std::vector<std::int64_t> ParseSizes(const std::string& key, const std::string& text) {
  std::vector<std::int64_t> sizes;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::size_t used = 0;
    std::int64_t size = 0;
    try {
      size = std::stoll(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || size < 1) {
      throw UserError(key + ": bad layer size '" + item + "' in '" + text + "'");
    }
    sizes.push_back(size);
  }
  if (sizes.empty()) throw UserError(key + ": no layer size in '" + text + "'");
  return sizes;
}

}  // namespace

void AddPpoKeys(ConfigSchema& schema) {
  schema.AddInt("ppo.total_steps", 3'000'000, "environment steps to train for (all worlds)", 1)
      .AddInt("ppo.n_envs", 8, "worlds stepped together", 1, 1024)
      .AddInt("ppo.n_steps", 1024, "steps per world and rollout", 1)
      .AddInt("ppo.batch_size", 32, "minibatch size", 1)
      .AddInt("ppo.n_epochs", 4, "passes over each rollout", 1)
      .AddDouble("ppo.gamma", 0.999, "discount factor", 0.0, 1.0)
      .AddDouble("ppo.gae_lambda", 0.98, "GAE lambda", 0.0, 1.0)
      .AddDouble("ppo.clip_range", 0.2, "PPO clip range", 0.0)
      .AddDouble("ppo.ent_coef", 0.01, "entropy bonus coefficient")
      .AddDouble("ppo.vf_coef", 0.5, "value loss coefficient", 0.0)
      .AddDouble("ppo.max_grad_norm", 0.5, "global gradient-norm clip", 0.0)
      .AddDouble("ppo.learning_rate", 2e-4, "Adam learning rate", 0.0)
      .AddDouble("ppo.adam_eps", 1e-5, "Adam epsilon", 0.0)
      .AddBool("ppo.normalize_advantage", true, "normalise advantages per minibatch")
      .AddString("policy.hidden_sizes", "128,64,32", "hidden layers of the actor and critic MLPs")
      .AddDouble("policy.log_std_init", 0.0, "initial log std of the action distribution")
      .AddString("extractor.name", "baseline", "perception feature extractor",
                 {"baseline", "vae-shallow", "vae-deep"})
      .AddString("extractor.encoder", "", "encoder.pt of train_vae (vae-shallow, vae-deep)")
      .AddBool("extractor.locked", true, "freeze the pre-trained encoder")
      .AddInt("extractor.latent_dims", 12, "latent size the encoder must have", 1)
      .AddString("extractor.baseline_convs", "1:45:15:15",
                 "baseline conv stack, out:kernel:stride:padding per layer")
      .AddInt("train.seed", 0, "master seed (initialisation, sampling, worlds)", 0)
      .AddInt("train.checkpoint_interval", 30'000, "steps between checkpoints", 1)
      .AddBool("train.keep_checkpoints", true, "keep every checkpoint's policy in checkpoints/")
      .AddInt("train.env_threads", 0, "threads stepping the worlds (0: one per core)", 0);
  AddEnvironmentKeys(schema);
}

PpoOptions PpoOptionsFrom(const Config& config) {
  PpoOptions options;
  options.total_steps = config.GetInt("ppo.total_steps");
  options.n_envs = static_cast<int>(config.GetInt("ppo.n_envs"));
  options.n_steps = static_cast<int>(config.GetInt("ppo.n_steps"));
  options.batch_size = static_cast<int>(config.GetInt("ppo.batch_size"));
  options.n_epochs = static_cast<int>(config.GetInt("ppo.n_epochs"));
  options.gamma = config.GetDouble("ppo.gamma");
  options.gae_lambda = config.GetDouble("ppo.gae_lambda");
  options.max_grad_norm = config.GetDouble("ppo.max_grad_norm");
  options.loss.clip_range = config.GetDouble("ppo.clip_range");
  options.loss.ent_coef = config.GetDouble("ppo.ent_coef");
  options.loss.vf_coef = config.GetDouble("ppo.vf_coef");
  options.loss.normalize_advantage = config.GetBool("ppo.normalize_advantage");
  options.adam.learning_rate = config.GetDouble("ppo.learning_rate");
  options.adam.eps = config.GetDouble("ppo.adam_eps");
  options.checkpoint_interval = config.GetInt("train.checkpoint_interval");
  options.keep_checkpoints = config.GetBool("train.keep_checkpoints");
  options.seed = static_cast<std::uint64_t>(config.GetInt("train.seed"));
  options.env_threads = static_cast<int>(config.GetInt("train.env_threads"));
  return options;
}

ActorCriticOptions ActorCriticOptionsFrom(const Config& config) {
  ActorCriticOptions options;
  options.extractor.kind = ParseExtractorKind(config.GetString("extractor.name"));
  options.extractor.encoder = config.GetString("extractor.encoder");
  options.extractor.locked = config.GetBool("extractor.locked");
  options.extractor.latent_dims = config.GetInt("extractor.latent_dims");
  options.extractor.baseline_convs = ParseConvStack(config.GetString("extractor.baseline_convs"));
  if (options.extractor.kind != ExtractorKind::kBaseline && options.extractor.encoder.empty()) {
    throw UserError(config.GetString("extractor.name") +
                    " needs a pre-trained encoder (--encoder ENCODER.pt)");
  }
  options.hidden_sizes = ParseSizes("policy.hidden_sizes", config.GetString("policy.hidden_sizes"));
  options.log_std_init = config.GetDouble("policy.log_std_init");
  options.seed = DeriveSeed(static_cast<std::uint64_t>(config.GetInt("train.seed")), "policy-init");
  return options;
}

}  // namespace colav

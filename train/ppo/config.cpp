#include "train/ppo/config.h"

#include <fmt/format.h>

#include <sstream>
#include <string>

#include "env/environment_config.h"
#include "env/training_scenario_config.h"
#include "src/error.h"
#include "src/seeding.h"

namespace colav {
namespace {

// Network sizes far beyond the paper's (hidden [128, 64, 32], one 1-channel conv) that still fit in
// memory; larger ones are typos.
constexpr std::int64_t kMaxLayerSize = 4096;
constexpr std::size_t kMaxLayers = 16;
constexpr std::int64_t kMaxConvChannels = 1024;
// Samples of one rollout (n_envs * n_steps) at most: 186 floats each, about 800 MB.
constexpr std::int64_t kMaxRolloutSamples = 1 << 20;
// Environment steps of a run at most: a thousand times the paper's 3 million.
constexpr std::int64_t kMaxSteps = 3'000'000'000;
// Fractions of the trained std for the deterministic action: 1 is the training policy's own mean
// action; ten times its noise is already far past any use.
constexpr double kMaxDeterministicStdScale = 10.0;

std::vector<std::int64_t> ParseLayerSizes(const std::string& text) {
  constexpr const char* kKey = "policy.hidden_sizes";
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
    if (used == 0 || used != item.size() || size < 1 || size > kMaxLayerSize) {
      throw UserError(fmt::format("{}: bad layer size '{}' in '{}'", kKey, item, text));
    }
    sizes.push_back(size);
  }
  if (sizes.empty()) throw UserError(fmt::format("{}: no layer size in '{}'", kKey, text));
  if (sizes.size() > kMaxLayers) {
    throw UserError(fmt::format("{}: more than {} layers in '{}'", kKey, kMaxLayers, text));
  }
  return sizes;
}

// extractor.encoder_closeness: "env" (the environment's own transform) or a transform's name.
constexpr const char* kEnvironmentCloseness = "env";

std::optional<ClosenessTransform> ParseEncoderCloseness(const std::string& name) {
  if (name == kEnvironmentCloseness) return std::nullopt;
  return ParseClosenessTransform(name);
}

std::string EncoderClosenessName(const std::optional<ClosenessTransform>& closeness) {
  return closeness ? ClosenessTransformName(*closeness) : kEnvironmentCloseness;
}

std::string LayerSizesText(const std::vector<std::int64_t>& sizes) {
  return fmt::format("{}", fmt::join(sizes, ","));
}

// ParseConvStack's errors named with the key, and channel counts bounded like the layer sizes.
std::vector<ConvLayerSpec> ParseBaselineConvs(const std::string& text) {
  constexpr const char* kKey = "extractor.baseline_convs";
  std::vector<ConvLayerSpec> layers;
  try {
    layers = ParseConvStack(text);
  } catch (const UserError& error) {
    throw UserError(std::string(kKey) + ": " + error.what());
  }
  for (const ConvLayerSpec& layer : layers) {
    if (layer.out_channels > kMaxConvChannels) {
      throw UserError(fmt::format("{}: {} output channels in '{}' (at most {})", kKey,
                                  layer.out_channels, text, kMaxConvChannels));
    }
  }
  return layers;
}

// A VAE extractor without an encoder file would train from random weights; the baseline would
// ignore one.
void RequireEncoder(PpoRunOptions& options) {
  const FeatureExtractorOptions& extractor = options.model.extractor;
  const bool baseline = extractor.kind == ExtractorKind::kBaseline;
  if (!baseline && extractor.encoder.empty()) {
    throw UserError(ExtractorKindName(extractor.kind) +
                    " needs a pre-trained encoder (--encoder ENCODER.pt)");
  }
  if (baseline && !extractor.encoder.empty()) {
    throw UserError("extractor.encoder " + extractor.encoder.string() +
                    ": the baseline extractor has no pre-trained encoder (use vae-shallow or "
                    "vae-deep)");
  }
}

// A minibatch is cut from one rollout; a rollout must fit in memory.
void RequireRolloutSizes(PpoRunOptions& options) {
  const PpoOptions& ppo = options.ppo;
  const std::int64_t samples = static_cast<std::int64_t>(ppo.n_envs) * ppo.n_steps;
  if (samples > kMaxRolloutSamples) {
    throw UserError(fmt::format("ppo.n_envs * ppo.n_steps = {} samples per rollout (at most {})",
                                samples, kMaxRolloutSamples));
  }
  if (ppo.batch_size > samples) {
    throw UserError(fmt::format(
        "ppo.batch_size = {} exceeds the {} samples of a rollout (ppo.n_envs * ppo.n_steps)",
        ppo.batch_size, samples));
  }
}

// A recurrent policy's minibatches are whole sequences of whole rollouts.
void RequireWholeSequences(PpoRunOptions& options) {
  const PpoOptions& ppo = options.ppo;
  if (options.model.recurrent_size == 0) return;
  if (ppo.n_steps % ppo.sequence_length != 0 || ppo.batch_size % ppo.sequence_length != 0) {
    throw UserError(fmt::format(
        "ppo.sequence_length = {} must divide ppo.n_steps ({}) and ppo.batch_size ({}) for a "
        "recurrent policy (policy.recurrent_size = {})",
        ppo.sequence_length, ppo.n_steps, ppo.batch_size, options.model.recurrent_size));
  }
}

// A setting of the memory's training without a memory, or two that contradict each other.
void RequireMemoryForItsTraining(PpoRunOptions& options) {
  const ActorCriticOptions& model = options.model;
  if (model.recurrent_size == 0 && !model.value_trains_memory) {
    throw UserError(
        "policy.value_trains_memory = false needs a memory (policy.recurrent_size > 0)");
  }
  if (model.recurrent_size == 0 && model.separate_critic_memory) {
    throw UserError(
        "policy.separate_critic_memory = true needs a memory (policy.recurrent_size > 0)");
  }
  if (model.separate_critic_memory && !model.value_trains_memory) {
    throw UserError(
        "policy.separate_critic_memory = true trains the critic's own memory on its loss: leave "
        "policy.value_trains_memory true");
  }
}

// A start from a policy file, whose navigation values were never normalised by this run's map.
void RequireRawNavigationForInitPolicy(PpoRunOptions& options) {
  if (!options.init_policy.empty() && options.ppo.normalize_navigation) {
    throw UserError("policy.init " + options.init_policy.string() +
                    ": its policy saw raw navigation values; leave ppo.normalize_navigation false");
  }
}

// A log std to keep or replace without a policy file to take it from.
void RequireInitPolicyForItsLogStd(PpoRunOptions& options) {
  if (options.init_policy.empty() && !options.init_keeps_log_std) {
    throw UserError("policy.init_keeps_log_std = false needs a policy.init file");
  }
}

// An expected clipped action for a policy whose actions are squashed, not clipped.
void RequireClippedActionsForDeterministicStd(PpoRunOptions& options) {
  if (options.model.squash_actions && options.model.smooths_deterministic_action()) {
    throw UserError(
        "policy.deterministic_thrust_std_scale and policy.deterministic_moment_std_scale average "
        "clipped actions: leave them 0 with policy.squash_actions = true");
  }
}

// A critic warm-up under which the actor would never train.
void RequireActorAfterWarmup(PpoRunOptions& options) {
  if (options.ppo.critic_warmup_steps >= options.ppo.total_steps) {
    throw UserError(fmt::format(
        "ppo.critic_warmup_steps = {} covers the whole run (ppo.total_steps {}): the actor would "
        "never train",
        options.ppo.critic_warmup_steps, options.ppo.total_steps));
  }
}

// A curriculum whose second stage no world would play.
void RequireSecondWorldsShare(PpoRunOptions& options) {
  if (options.second_worlds_from_step > 0 &&
      SecondKindWorlds(options.second_worlds_share, options.ppo.n_envs) == 0) {
    throw UserError(fmt::format(
        "world2.from_step = {}: no world plays world2.* (world2.share {} of {} worlds)",
        options.second_worlds_from_step, options.second_worlds_share, options.ppo.n_envs));
  }
}

// What the model takes from the rest of the configuration: its seed, and as many scans per
// observation as the environment gives.
void DeriveModelSettings(PpoRunOptions& options) {
  options.model.seed = DeriveSeed(options.ppo.seed, "policy-init");
  options.model.extractor.scans = ScansPerObservation(options.env);
}

}  // namespace

EnvironmentConfig AuthorsTrainingEnvironment() {
  EnvironmentConfig config;
  config.closeness = ClosenessTransform::kLog;
  return config;
}

std::vector<TrainingScenarioConfig> WorldScenarios(const PpoRunOptions& options,
                                                   std::int64_t step) {
  const double second_share =
      step < options.second_worlds_from_step ? 0.0 : options.second_worlds_share;
  return MixedWorlds(options.worlds, options.second_worlds, second_share, options.ppo.n_envs);
}

OptionsBinding<PpoRunOptions> PpoRunBinding() {
  using Run = PpoRunOptions;
  OptionsBinding<Run> binding;
  binding
      .Number(
          "ppo.total_steps", [](Run & o) -> auto& { return o.ppo.total_steps; },
          "environment steps to train for (all worlds); SB3 keeps collecting while steps < "
          "total: 367 rollouts, 3,006,464 steps",
          1, kMaxSteps)
      .Number(
          "ppo.n_envs", [](Run & o) -> auto& { return o.ppo.n_envs; }, "worlds stepped together", 1,
          1024)
      .Number(
          "ppo.n_steps", [](Run & o) -> auto& { return o.ppo.n_steps; },
          "steps per world and rollout (8 worlds: 8,192 samples per rollout)", 1,
          kMaxRolloutSamples)
      .Number(
          "ppo.batch_size", [](Run & o) -> auto& { return o.ppo.batch_size; },
          "minibatch size (at most one rollout)", 1, kMaxRolloutSamples)
      .Number(
          "ppo.n_epochs", [](Run & o) -> auto& { return o.ppo.n_epochs; },
          "passes over each rollout", 1, 1000)
      .Number(
          "ppo.gamma", [](Run & o) -> auto& { return o.ppo.gamma; }, "discount factor", 0.0, 1.0)
      .Number(
          "ppo.gae_lambda", [](Run & o) -> auto& { return o.ppo.gae_lambda; }, "GAE lambda", 0.0,
          1.0)
      .Number(
          "ppo.sequence_length", [](Run & o) -> auto& { return o.ppo.sequence_length; },
          "recurrent policies: steps per sequence of a minibatch (ppo.batch_size / this "
          "sequences, backpropagated through their steps); must divide ppo.n_steps and "
          "ppo.batch_size",
          1, 1 << 20)
      .Number(
          "ppo.clip_range", [](Run & o) -> auto& { return o.ppo.loss.clip_range; },
          "PPO clip range", 0.0, 10.0)
      .Number(
          "ppo.ent_coef", [](Run & o) -> auto& { return o.ppo.loss.ent_coef; },
          "entropy bonus coefficient", -10.0, 10.0)
      .Number(
          "ppo.vf_coef", [](Run & o) -> auto& { return o.ppo.loss.vf_coef; },
          "value loss coefficient", 0.0, 100.0)
      .Bool(
          "ppo.timeouts_terminal", [](Run & o) -> auto& { return o.ppo.timeouts_terminal; },
          "end a timed-out episode's return like a terminal state (the reference) instead of "
          "bootstrapping it with V(final observation) (SB3)")
      .Bool(
          "ppo.normalize_reward", [](Run & o) -> auto& { return o.ppo.normalize_reward; },
          "scale the rewards the learner sees by the running std of the discounted return, "
          "clipped to +-10 (SB3's VecNormalize norm_reward; logs keep the environment's rewards)")
      .Bool(
          "ppo.normalize_navigation", [](Run & o) -> auto& { return o.ppo.normalize_navigation; },
          "normalise the 6 navigation values the policy sees by their running mean and std (SB3's "
          "VecNormalize norm_obs on the navigation values only, not clipped; policy.pt applies it)")
      .Number(
          "ppo.max_grad_norm", [](Run & o) -> auto& { return o.ppo.max_grad_norm; },
          "global gradient-norm clip", 0.0, 1e6)
      .Number(
          "ppo.std_max", [](Run & o) -> auto& { return o.ppo.std_max; },
          "the action distribution's largest std: its log std is clamped to log(std_max) at the "
          "start and after each Adam step; 0: unbounded (SB3's)",
          0.0, 1e6)
      .Number(
          "ppo.learning_rate", [](Run & o) -> auto& { return o.ppo.adam.learning_rate; },
          "Adam learning rate", 0.0, 1.0)
      .Coded("ppo.learning_rate_schedule",
             [](Run & o) -> auto& { return o.ppo.learning_rate_schedule; },
             "learning rate over the run: constant, or linear from ppo.learning_rate to 0 at "
             "ppo.total_steps (set before each update, SB3's progress remaining)",
             TextCodec<LearningRateSchedule>{LearningRateScheduleName, ParseLearningRateSchedule},
             {"constant", "linear"})
      .Number(
          "ppo.critic_warmup_steps", [](Run & o) -> auto& { return o.ppo.critic_warmup_steps; },
          "updates of rollouts ending at or before this step train the critic alone, the actor "
          "(its trunk, head, log std, extractor and memory) held; Adam restarts when the actor "
          "joins. For runs from policy.init; 0: none",
          0, kMaxSteps)
      .Number(
          "ppo.adam_eps", [](Run & o) -> auto& { return o.ppo.adam.eps; }, "Adam epsilon", 0.0, 1.0)
      .Bool(
          "ppo.normalize_advantage",
          [](Run & o) -> auto& { return o.ppo.loss.normalize_advantage; },
          "normalise advantages per minibatch")
      .Coded(
          "policy.hidden_sizes", [](Run & o) -> auto& { return o.model.hidden_sizes; },
          "hidden layers of the actor and critic MLPs (separate, Tanh)",
          TextCodec<std::vector<std::int64_t>>{LayerSizesText, ParseLayerSizes})
      .Text(
          "policy.init", [](Run & o) -> auto& { return o.init_policy; },
          "policy.pt (of train_ppo or distill_policy.py, of this run's architecture and "
          "observations) whose weights the run starts from; empty: its own initialisation")
      .Bool(
          "policy.init_keeps_log_std", [](Run & o) -> auto& { return o.init_keeps_log_std; },
          "with policy.init: keep the file's log std (true) or start from policy.log_std_init "
          "(false)")
      .Number(
          "policy.log_std_init", [](Run & o) -> auto& { return o.model.log_std_init; },
          "initial log std of the action distribution (std e^-10 to e^2)", -10.0, 2.0)
      .Number(
          "policy.recurrent_size", [](Run & o) -> auto& { return o.model.recurrent_size; },
          "size of the memory: a GRU between the extractor and the actor and critic, whose state "
          "(0 at each episode's start) both read beside the features; 0: none (the paper's)",
          0, 1024)
      .Bool(
          "policy.value_trains_memory",
          [](Run & o) -> auto& { return o.model.value_trains_memory; },
          "whether the critic's loss trains the memory as the actor's does; false: the critic "
          "reads the state detached (SB3-contrib's shared LSTM)")
      .Bool(
          "policy.separate_critic_memory",
          [](Run & o) -> auto& { return o.model.separate_critic_memory; },
          "give the critic a memory of its own (SB3-contrib's default) instead of the actor's; "
          "each is trained by its own loss")
      .Number(
          "policy.critic_vessels", [](Run & o) -> auto& { return o.model.critic_vessels; },
          "a privileged critic: it also reads the true position, motion and width of this many "
          "nearest moving vessels within 300 m, in the agent's frame (training only; the policy "
          "and the test see the observation alone); 0: the critic sees what the actor sees (the "
          "paper's)",
          0, 16)
      .Bool(
          "policy.squash_actions", [](Run & o) -> auto& { return o.model.squash_actions; },
          "act with tanh of the Gaussian's sample (deterministic: of its mean) instead of clipping "
          "it to [-1, 1]; the entropy bonus is then the bounded distribution's")
      .Number(
          "policy.deterministic_thrust_std_scale",
          [](Run & o) -> auto& { return o.model.deterministic_std_scale[0]; },
          "the exported policy's thrust: E[clip(u, -1, 1)], u ~ N(mean, (scale * std)^2), the "
          "mean thrust of the training policy at this fraction of its std; 0: the clipped mean "
          "(SB3's); training is unchanged",
          0.0, kMaxDeterministicStdScale)
      .Number(
          "policy.deterministic_moment_std_scale",
          [](Run & o) -> auto& { return o.model.deterministic_std_scale[1]; },
          "the same for the exported policy's yaw moment (rudder)", 0.0, kMaxDeterministicStdScale)
      .Coded("extractor.name", [](Run & o) -> auto& { return o.model.extractor.kind; },
             "perception feature extractor",
             TextCodec<ExtractorKind>{ExtractorKindName, ParseExtractorKind},
             {"baseline", "vae-shallow", "vae-deep"})
      .Text(
          "extractor.encoder", [](Run & o) -> auto& { return o.model.extractor.encoder; },
          "encoder.pt of train_vae (vae-shallow, vae-deep)")
      .Bool(
          "extractor.locked", [](Run & o) -> auto& { return o.model.extractor.locked; },
          "freeze the pre-trained encoder")
      .Coded("extractor.head", [](Run & o) -> auto& { return o.model.extractor.head; },
             "vae-*: the pre-trained fc_mu (mu), or fc_mu re-drawn orthogonal x sqrt 2 with a "
             "ReLU, as the authors' agents had it (reference)",
             TextCodec<EncoderHead>{EncoderHeadName, ParseEncoderHead}, {"mu", "reference"})
      .Coded(
          "extractor.encoder_closeness", [](Run & o) -> auto& { return o.encoder_closeness; },
          "vae-*: the closeness transform the encoder must have been trained on (env: "
          "env.closeness); linear: the paper recipe, log closeness fed to a linear-trained VAE",
          TextCodec<std::optional<ClosenessTransform>>{EncoderClosenessName, ParseEncoderCloseness},
          {"env", "linear", "log"})
      .Number(
          "extractor.latent_dims", [](Run & o) -> auto& { return o.model.extractor.latent_dims; },
          "latent size the encoder must have", 1, 4096)
      .Coded(
          "extractor.baseline_convs",
          [](Run & o) -> auto& { return o.model.extractor.baseline_convs; },
          "baseline conv stack, out:kernel:stride:padding per circular conv layer",
          TextCodec<std::vector<ConvLayerSpec>>{ConvStackText, ParseBaselineConvs})
      .Number(
          "train.seed", [](Run & o) -> auto& { return o.ppo.seed; },
          "master seed (initialisation, sampling, worlds)", 0)
      .Number(
          "train.checkpoint_interval", [](Run & o) -> auto& { return o.ppo.checkpoint_interval; },
          "steps between checkpoints", 1, kMaxSteps)
      .Bool(
          "train.keep_checkpoints", [](Run & o) -> auto& { return o.ppo.keep_checkpoints; },
          "keep every checkpoint's policy in checkpoints/")
      .Number(
          "train.env_threads", [](Run & o) -> auto& { return o.ppo.env_threads; },
          "threads stepping the worlds (0: one per core)", 0, 256)
      .Include(EnvironmentBinding(), &Run::env)
      .Include(TrainingScenarioBinding("world"), &Run::worlds)
      .Include(TrainingScenarioBinding("world2"), &Run::second_worlds)
      .Number(
          "world2.share", [](Run & o) -> auto& { return o.second_worlds_share; },
          "share of the training worlds (rounded to whole worlds, the last ones) playing the "
          "world2.* scenario instead of world.*; 0: none",
          0.0, 1.0)
      .Number(
          "world2.from_step", [](Run & o) -> auto& { return o.second_worlds_from_step; },
          "a curriculum: the world2.share worlds play world.* until the first rollout starting at "
          "or after this step, then world2.*; 0: world2.* from the start",
          0, kMaxSteps)
      .Then(RequireSecondWorldsShare)
      .Then(RequireActorAfterWarmup)
      .Then(RequireEncoder)
      .Then(RequireRolloutSizes)
      .Then(RequireWholeSequences)
      .Then(RequireMemoryForItsTraining)
      .Then(RequireClippedActionsForDeterministicStd)
      .Then(RequireRawNavigationForInitPolicy)
      .Then(RequireInitPolicyForItsLogStd)
      .Then(DeriveModelSettings);
  return binding;
}

}  // namespace colav

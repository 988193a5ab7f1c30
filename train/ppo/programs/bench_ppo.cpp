// bench_ppo: times the PPO learner without the simulator, on synthetic rollouts: one update of a
// full rollout (n_steps x n_envs samples, n_epochs passes of minibatches) and the batched policy
// forward of a rollout step, for each of the paper's five configurations and the shallow locked
// one with a memory (policy.recurrent_size 32, sequences of ppo.sequence_length), shared or one
// each for actor and critic (policy.separate_critic_memory). Times are the
// thread's CPU time (steady under load from other processes; on an idle machine they equal wall
// time). Ends with headline lines `update_us_per_minibatch_<config>: N`,
// `policy_us_per_step_<config>: N` and `learner_s_per_3m_steps_<config>: N` (the learner's share of
// a 3,000,000-step run).
#include <ATen/CPUGeneratorImpl.h>
#include <time.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>
#include <vector>

#include "src/cli.h"
#include "src/number_flag.h"
#include "train/ppo/config.h"
#include "train/ppo/update.h"

namespace {

double ThreadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

constexpr double kRunSteps = 3'000'000;

struct Configuration {
  std::string name;
  colav::ExtractorKind kind;
  bool locked;
  int recurrent_size = 0;
  bool separate_critic_memory = false;
};

// Random observations and actions, rewards of -1, 0 or 1, episodes of 300 steps; with a memory,
// random states in (-1, 1) (a GRU's range), 0 where an episode starts.
colav::RolloutBuffer SyntheticRollout(const colav::PpoOptions& options, int state_size) {
  colav::RolloutBuffer buffer(options.n_steps, options.n_envs, colav::kObservationSize, state_size);
  const int N = options.n_envs;
  torch::Generator generator = at::make_generator<at::CPUGeneratorImpl>(1);
  for (int t = 0; t < options.n_steps; ++t) {
    const torch::Tensor obs = torch::rand({N, colav::kObservationSize}, generator);
    std::copy_n(obs.data_ptr<float>(), obs.numel(), buffer.observations(t));
    const torch::Tensor actions = torch::randn({N, colav::kActionSize}, generator);
    std::copy_n(actions.data_ptr<float>(), actions.numel(), buffer.actions(t));
    for (int e = 0; e < N; ++e) {
      buffer.log_probs(t)[e] = -2.0f;
      buffer.rewards(t)[e] = static_cast<float>(e % 3) - 1.0f;
      buffer.dones(t)[e] = (t % 300) == 299;
    }
    if (state_size == 0) continue;
    const bool episode_start = t % 300 == 0;
    const torch::Tensor states = episode_start ? torch::zeros({N, state_size})
                                               : torch::rand({N, state_size}, generator) * 2 - 1;
    std::copy_n(states.data_ptr<float>(), states.numel(), buffer.states(t));
  }
  buffer.ComputeReturnsAndAdvantages(options.gamma, options.gae_lambda);
  return buffer;
}

int Main(int argc, char** argv) {
  CLI::App app{"Times the PPO learner (update and policy forward) on synthetic rollouts."};
  int rollouts = 2;
  colav::AddNumberFlag(app, "--rollouts", rollouts, "updates timed per configuration", 1, 1000);
  const colav::ConfigFlags config_flags(app, colav::ConfigSchema());  // no keys; --print-config
  colav::ParseCommandLine(app, argc, argv);
  config_flags.Resolve();  // no keys: rejects any in --set or --config
  torch::set_num_threads(1);

  const colav::PpoOptions options;
  constexpr int kRecurrentSize = 32;
  const double rollout_samples = static_cast<double>(options.n_steps) * options.n_envs;
  const double minibatches_per_update = options.n_epochs * rollout_samples / options.batch_size;
  const std::vector<Configuration> configurations = {
      {"baseline", colav::ExtractorKind::kBaseline, false},
      {"shallow_locked", colav::ExtractorKind::kVaeShallow, true},
      {"shallow_unlocked", colav::ExtractorKind::kVaeShallow, false},
      {"deep_locked", colav::ExtractorKind::kVaeDeep, true},
      {"deep_unlocked", colav::ExtractorKind::kVaeDeep, false},
      {"shallow_locked_recurrent32", colav::ExtractorKind::kVaeShallow, true, kRecurrentSize},
      {"shallow_locked_recurrent32_critic_memory", colav::ExtractorKind::kVaeShallow, true,
       kRecurrentSize, true}};
  std::vector<std::string> headlines;
  for (const Configuration& configuration : configurations) {
    colav::ActorCriticOptions model_options;
    model_options.extractor.kind = configuration.kind;  // untrained encoder: same cost
    model_options.extractor.locked = configuration.locked;
    model_options.recurrent_size = configuration.recurrent_size;
    model_options.separate_critic_memory = configuration.separate_critic_memory;
    // The same synthetic rollout for every configuration, with states of the model's size.
    const colav::RolloutBuffer buffer =
        SyntheticRollout(options, static_cast<int>(model_options.state_size()));
    colav::PpoUpdater updater(colav::ActorCritic(model_options), options);
    auto generator = at::make_generator<at::CPUGeneratorImpl>(0);
    updater.Update(buffer, generator);  // warm-up

    double start = ThreadCpuSeconds();
    for (int i = 0; i < rollouts; ++i) updater.Update(buffer, generator);
    const double update_s = (ThreadCpuSeconds() - start) / rollouts;

    std::vector<float> mean(options.n_envs * colav::kActionSize), value(options.n_envs);
    std::vector<float> states(static_cast<std::size_t>(options.n_envs) *
                              model_options.state_size());
    float* step_states = configuration.recurrent_size > 0 ? states.data() : nullptr;
    start = ThreadCpuSeconds();
    for (int t = 0; t < options.n_steps; ++t) {
      updater.policy().Predict(buffer.observations().data() + static_cast<std::ptrdiff_t>(t) *
                                                                  options.n_envs *
                                                                  colav::kObservationSize,
                               options.n_envs, mean.data(), value.data(), step_states);
    }
    const double predict_s = (ThreadCpuSeconds() - start) / options.n_steps;

    const double rollouts_per_run = kRunSteps / rollout_samples;
    const double learner_s = rollouts_per_run * (update_s + options.n_steps * predict_s);
    std::cout << configuration.name << ": update " << update_s << " s per rollout ("
              << 1e6 * update_s / minibatches_per_update << " us per minibatch of "
              << options.batch_size << "), policy forward " << 1e6 * predict_s << " us per step of "
              << options.n_envs << " worlds\n";
    headlines.push_back("update_us_per_minibatch_" + configuration.name + ": " +
                        std::to_string(1e6 * update_s / minibatches_per_update));
    headlines.push_back("policy_us_per_step_" + configuration.name + ": " +
                        std::to_string(1e6 * predict_s));
    headlines.push_back("learner_s_per_3m_steps_" + configuration.name + ": " +
                        std::to_string(learner_s));
  }
  for (const std::string& line : headlines) std::cout << line << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return colav::RunProgram("bench_ppo", argc, argv, Main); }

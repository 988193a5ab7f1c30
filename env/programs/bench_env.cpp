// bench_env: environment throughput (steps per second), single-threaded and batched (stepped
// together, and with --async-batch asynchronously, EnvPool style), plus the cost of the hot-path
// pieces. Ends with the headline lines of shared/spec/interfaces.md.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>

#include "env/async_environment.h"
#include "env/batched_environment.h"
#include "env/environment.h"
#include "env/training_scenario.h"
#include "src/cli.h"
#include "src/error.h"
#include "src/number_flag.h"
#include "src/random.h"
#include "src/threads/thread_pool.h"

namespace colav {
namespace {

using Clock = std::chrono::steady_clock;

// As many worlds and threads as train_ppo's ppo.n_envs and a machine can use.
constexpr int kMaxEnvs = 1024;
constexpr int kMaxThreads = 256;

// Runs `step` (which performs `per_call` env steps) repeatedly for about `seconds` and returns
// steps per second.
double Throughput(double seconds, std::int64_t per_call, const std::function<void()>& step) {
  for (int k = 0; k < 100; ++k) step();  // warm-up
  std::int64_t steps = 0;
  const auto start = Clock::now();
  double elapsed = 0.0;
  while (elapsed < seconds) {
    for (int k = 0; k < 100; ++k) step();
    steps += 100 * per_call;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  }
  return static_cast<double>(steps) / elapsed;
}

// One environment, auto-resetting; `random_actions` draws uniform actions, else full thrust
// straight ahead.
double SingleEnvironment(double seconds, bool random_actions, std::uint64_t seed) {
  Environment env(EnvironmentConfig{}, std::make_shared<TrainingScenarioGenerator>());
  std::vector<float> observation(kObservationSize);
  std::uint64_t episode = 0;
  env.Reset(DeriveSeed(seed, "bench", episode), observation.data());
  Rng rng(seed);
  return Throughput(seconds, 1, [&] {
    double action[kActionSize] = {1.0, 0.0};
    if (random_actions) {
      action[0] = Uniform(rng, -1.0, 1.0);
      action[1] = Uniform(rng, -1.0, 1.0);
    }
    const StepResult result = env.Step(action, observation.data());
    if (result.terminated || result.truncated) {
      env.Reset(DeriveSeed(seed, "bench", ++episode), observation.data());
    }
  });
}

double Batched(double seconds, int num_envs, int num_threads, std::uint64_t seed) {
  BatchedEnvironment envs(EnvironmentConfig{}, num_envs, num_threads, seed);
  envs.Reset();
  Rng rng(seed);
  std::vector<float> actions(static_cast<std::size_t>(num_envs) * kActionSize);
  return Throughput(seconds, num_envs, [&] {
    for (float& a : actions) a = static_cast<float>(Uniform(rng, -1.0, 1.0));
    envs.Step(actions.data());
  });
}

// Recv a batch, draw its actions, Send them: the loop of an EnvPool-style trainer.
double Asynchronous(double seconds, int num_envs, int batch_size, int num_threads,
                    std::uint64_t seed) {
  AsyncEnvironmentPool pool(EnvironmentConfig{}, num_envs, batch_size, num_threads, seed);
  pool.Reset();
  Rng rng(seed);
  std::vector<float> actions(static_cast<std::size_t>(batch_size) * kActionSize);
  return Throughput(seconds, batch_size, [&] {
    pool.Recv();
    for (float& a : actions) a = static_cast<float>(Uniform(rng, -1.0, 1.0));
    pool.Send(actions.data(), pool.env_ids(), batch_size);
  });
}

int BenchEnv(int argc, char** argv) {
  CLI::App app{"Measures environment steps per second (training environment of the paper)."};
  double seconds = 3.0;
  int num_envs = 8;
  int num_threads = ThreadCountOrAllCores(0);
  std::uint64_t seed = 1;
  AddNumberFlag(app, "--seconds", seconds, "measuring time per case", 0.01, 3600.0);
  AddNumberFlag(app, "--envs", num_envs, "worlds in the batched case", 1, kMaxEnvs);
  AddNumberFlag(app, "--threads", num_threads, "threads in the batched case (default: all cores)",
                1, kMaxThreads);
  int async_batch = 0;
  AddNumberFlag(app, "--async-batch", async_batch,
                "also step the worlds asynchronously, EnvPool style, in batches of this many "
                "(at most --envs; 0: not)",
                0, kMaxEnvs);
  AddNumberFlag<std::uint64_t>(app, "--seed", seed, "seed of the worlds and actions", 0,
                               std::numeric_limits<std::uint64_t>::max());
  const ConfigFlags config_flags(app, ConfigSchema());  // no keys; --print-config as everywhere
  ParseCommandLine(app, argc, argv);
  config_flags.Resolve();  // no keys: rejects any in --set or --config
  if (async_batch > num_envs) {
    throw UserError("--async-batch: " + std::to_string(async_batch) + " is more than --envs " +
                    std::to_string(num_envs));
  }

  const double fixed = SingleEnvironment(seconds, false, seed);
  std::printf("1 thread, fixed action (full thrust)   %12.0f steps/s\n", fixed);
  const double random = SingleEnvironment(seconds, true, seed);
  std::printf("1 thread, random actions              %12.0f steps/s\n", random);
  const double batched_one_thread = Batched(seconds, num_envs, 1, seed);
  std::printf("%d worlds on 1 thread, random actions  %12.0f steps/s\n", num_envs,
              batched_one_thread);
  const double batched = Batched(seconds, num_envs, num_threads, seed);
  std::printf("%d worlds on %d threads, random actions %12.0f steps/s (%.2fx of 1 thread)\n",
              num_envs, num_threads, batched, batched / batched_one_thread);
  if (async_batch > 0) {
    const double asynchronous = Asynchronous(seconds, num_envs, async_batch, num_threads, seed);
    std::printf("%d worlds on %d threads, async batches of %d %12.0f steps/s (%.2fx of 1 thread)\n",
                num_envs, num_threads, async_batch, asynchronous,
                asynchronous / batched_one_thread);
  }
  std::printf("env_steps_per_s_1thread: %.0f\nenv_steps_per_s_batched: %.0f\n", random, batched);
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("bench_env", argc, argv, colav::BenchEnv);
}

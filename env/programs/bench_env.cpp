// bench_env: environment throughput (steps per second), single-threaded and batched (stepped
// together, and with --async-batch asynchronously, EnvPool style), against the ceiling of the
// batched case: the same worlds stepped by independent threads.
// Ends with the headline lines of shared/spec/interfaces.md.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

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
// Stepping before a case is measured, so that its worlds' memory is warm.
constexpr double kWarmUpSeconds = 0.01;

// Steps performed and the time they took.
struct Measured {
  std::int64_t steps = 0;
  double seconds = 0.0;
  double PerSecond() const { return static_cast<double>(steps) / seconds; }
};

// Calls `step` (which performs `per_call` env steps) in blocks of 100 for about `seconds`.
Measured Run(double seconds, std::int64_t per_call, const std::function<void()>& step) {
  Measured measured;
  const auto start = Clock::now();
  while (measured.seconds < seconds) {
    for (int k = 0; k < 100; ++k) step();
    measured.steps += 100 * per_call;
    measured.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  }
  return measured;
}

void WarmUp(const std::function<void()>& step) {
  for (int k = 0; k < 100; ++k) step();
}

// Steps per second of `step` over about `seconds`, after a warm-up.
double Throughput(double seconds, std::int64_t per_call, const std::function<void()>& step) {
  WarmUp(step);
  return Run(seconds, per_call, step).PerSecond();
}

// A case measured against the 1-thread case in alternating rounds.
struct Case {
  std::function<Measured(double seconds)> measure;  ///< steps for about `seconds`
  Measured total;
  std::vector<double> ratios;  ///< of each round's rate to the 1-thread rate of the same round
};

// Measures one round of `c`, adds it to c's total and returns its rate.
double MeasureRound(double seconds, Case& c) {
  const Measured measured = c.measure(seconds);
  c.total.steps += measured.steps;
  c.total.seconds += measured.seconds;
  return measured.PerSecond();
}

// Measures `one_thread` and each of `others` in `rounds` alternating rounds of seconds / rounds
// each: the speed of this virtual machine drifts by 15 % or more over a few seconds (1-thread
// runs of the same binary a few seconds apart gave 272,000-355,000 steps/s), and a drift falls on
// the cases of one round alike.
void MeasureInRounds(double seconds, int rounds, Case& one_thread,
                     const std::vector<Case*>& others) {
  one_thread.measure(kWarmUpSeconds);
  for (Case* c : others) c->measure(kWarmUpSeconds);
  for (int round = 0; round < rounds; ++round) {
    const double one_thread_rate = MeasureRound(seconds / rounds, one_thread);
    for (Case* c : others) {
      c->ratios.push_back(MeasureRound(seconds / rounds, *c) / one_thread_rate);
    }
  }
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
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

// Uniform random actions for `count` worlds, drawn anew by each Draw().
class RandomActions {
 public:
  RandomActions(int count, std::uint64_t seed)
      : rng_(seed), actions_(static_cast<std::size_t>(count) * kActionSize) {}
  const float* Draw() {
    for (float& a : actions_) a = static_cast<float>(Uniform(rng_, -1.0, 1.0));
    return actions_.data();
  }

 private:
  Rng rng_;
  std::vector<float> actions_;
};

Case Batched(int num_envs, int num_threads, std::uint64_t seed) {
  auto envs =
      std::make_shared<BatchedEnvironment>(EnvironmentConfig{}, num_envs, num_threads, seed);
  envs->Reset();
  auto actions = std::make_shared<RandomActions>(num_envs, seed);
  Case batched;
  batched.measure = [envs, actions, num_envs](double seconds) {
    return Run(seconds, num_envs, [&] { envs->Step(actions->Draw()); });
  };
  return batched;
}

// The ceiling of the batched case on this machine: the worlds split into one group per thread,
// each group a 1-thread batched case stepped by its own thread, with no hand-over between them.
Case Independent(int num_envs, int threads_wanted, std::uint64_t seed) {
  const int num_threads = std::min(threads_wanted, num_envs);  // as BatchedEnvironment's pool
  auto groups = std::make_shared<std::vector<Case>>();
  for (int k = 0; k < num_threads; ++k) {
    groups->push_back(Batched(ThreadPool::ShareStart(num_envs, num_threads, k + 1) -
                                  ThreadPool::ShareStart(num_envs, num_threads, k),
                              1, DeriveSeed(seed, "bench-group", k)));
  }
  Case independent;
  independent.measure = [groups](double seconds) {
    std::vector<Measured> measured(groups->size());
    std::vector<std::thread> threads;
    for (std::size_t k = 0; k < groups->size(); ++k) {
      threads.emplace_back([&, k] { measured[k] = (*groups)[k].measure(seconds); });
    }
    for (std::thread& thread : threads) thread.join();
    Measured all;
    for (const Measured& m : measured) {
      all.steps += m.steps;
      all.seconds = std::max(all.seconds, m.seconds);
    }
    return all;
  };
  return independent;
}

// Recv a batch, draw its actions, Send them: the loop of an EnvPool-style trainer.
Case Asynchronous(int num_envs, int batch_size, int num_threads, std::uint64_t seed) {
  auto pool = std::make_shared<AsyncEnvironmentPool>(EnvironmentConfig{}, num_envs, batch_size,
                                                     num_threads, seed);
  pool->Reset();
  auto actions = std::make_shared<RandomActions>(batch_size, seed);
  Case asynchronous;
  asynchronous.measure = [pool, actions, batch_size](double seconds) {
    return Run(seconds, batch_size, [&] {
      pool->Recv();
      pool->Send(actions->Draw(), pool->env_ids(), batch_size);
    });
  };
  return asynchronous;
}

// The rate of `c` over all its rounds, its ratio to the 1-thread case's, and the spread of the
// rounds' ratios.
void PrintAgainstOneThread(const std::string& label, const Case& c, const Case& one_thread) {
  const auto [lowest, highest] = std::minmax_element(c.ratios.begin(), c.ratios.end());
  std::printf("%-44s %9.0f steps/s (%.2fx of 1 thread; rounds %.2f-%.2fx, median %.2fx)\n",
              label.c_str(), c.total.PerSecond(),
              c.total.PerSecond() / one_thread.total.PerSecond(), *lowest, *highest,
              Median(c.ratios));
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
  int rounds = 10;
  AddNumberFlag(app, "--rounds", rounds,
                "the batched cases are measured in this many alternating rounds, so that a drift "
                "of the machine's speed falls on all alike",
                1, 1000);
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
  Case one_thread = Batched(num_envs, 1, seed);
  Case batched = Batched(num_envs, num_threads, seed);
  Case independent = Independent(num_envs, num_threads, seed);
  std::vector<Case*> against_one_thread = {&batched, &independent};
  Case asynchronous;
  if (async_batch > 0) {
    asynchronous = Asynchronous(num_envs, async_batch, num_threads, seed);
    against_one_thread.push_back(&asynchronous);
  }
  MeasureInRounds(seconds, rounds, one_thread, against_one_thread);
  std::printf("%-44s %9.0f steps/s (%d alternating rounds of %.2f s per case)\n",
              (std::to_string(num_envs) + " worlds on 1 thread, random actions").c_str(),
              one_thread.total.PerSecond(), rounds, seconds / rounds);
  PrintAgainstOneThread(std::to_string(num_envs) + " worlds on " + std::to_string(num_threads) +
                            " threads, random actions",
                        batched, one_thread);
  PrintAgainstOneThread(std::to_string(num_envs) + " worlds in " + std::to_string(num_threads) +
                            " independent threads (ceiling)",
                        independent, one_thread);
  if (async_batch > 0) {
    PrintAgainstOneThread(std::to_string(num_envs) + " worlds on " + std::to_string(num_threads) +
                              " threads, async batches of " + std::to_string(async_batch),
                          asynchronous, one_thread);
  }
  // What the hand-over between the threads keeps of what this machine's threads can do at all.
  const double ceiling = independent.total.PerSecond();
  std::printf("share of the ceiling: synchronous %.2f", batched.total.PerSecond() / ceiling);
  if (async_batch > 0) {
    std::printf(", async batches of %d %.2f", async_batch,
                asynchronous.total.PerSecond() / ceiling);
  }
  std::printf("\n");
  std::printf("env_steps_per_s_1thread: %.0f\nenv_steps_per_s_batched: %.0f\n", random,
              batched.total.PerSecond());
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("bench_env", argc, argv, colav::BenchEnv);
}

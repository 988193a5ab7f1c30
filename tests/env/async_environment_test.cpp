// Asynchronous pool: each world plays the synchronous environment's trajectory whatever the
// order worlds come back in; batches, argument checks, shutdown with work in flight.
#include "env/async_environment.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <future>
#include <map>
#include <set>
#include <stdexcept>
#include <thread>

#include "env/training_scenario.h"

namespace colav {
namespace {

constexpr std::uint64_t kSeed = 11;

// A deterministic action of world `world` on its step `step`, sometimes outside [-1, 1] (clipped)
// and of float precision, so the float send path is exercised.
void ActionOf(int world, int step, float* action) {
  action[0] = static_cast<float>(1.3 * std::sin(0.7 * world + 0.31 * step));
  action[1] = static_cast<float>(1.2 * std::cos(1.1 * world + 0.17 * step));
}

// A short episode limit, so that every world auto-resets several times in a run.
EnvironmentConfig ShortEpisodes() {
  EnvironmentConfig config;
  config.max_steps = 9;
  return config;
}

// What one world gives back on one step (or on its reset, as its first entry).
struct WorldResult {
  std::vector<float> observation;
  float reward = 0.0f;
  bool terminated = false;
  bool truncated = false;
  std::vector<float> final_observation;  // empty unless the episode ended
  std::optional<double> finished_return;

  bool operator==(const WorldResult& other) const {
    return observation == other.observation && reward == other.reward &&
           terminated == other.terminated && truncated == other.truncated &&
           final_observation == other.final_observation && finished_return == other.finished_return;
  }
};

// Row `row` of a set of results.
WorldResult ResultRow(const float* observations, const float* final_observations,
                      const float* rewards, const std::uint8_t* terminated,
                      const std::uint8_t* truncated,
                      const std::vector<std::optional<EpisodeMetrics>>& finished, int row) {
  const float* observation = observations + row * kObservationSize;
  WorldResult result;
  result.observation.assign(observation, observation + kObservationSize);
  result.reward = rewards[row];
  result.terminated = terminated[row] != 0;
  result.truncated = truncated[row] != 0;
  if (result.terminated || result.truncated) {
    const float* last = final_observations + row * kObservationSize;
    result.final_observation.assign(last, last + kObservationSize);
  }
  if (finished[row]) result.finished_return = finished[row]->cumulative_reward;
  return result;
}

using Trajectories = std::vector<std::vector<WorldResult>>;  // per world: reset, then each step

// `steps` steps of every world of `envs` (reset first) with ActionOf.
Trajectories SynchronousRun(BatchedEnvironment& envs, int steps) {
  const int n = envs.num_envs();
  Trajectories runs(n);
  const auto record = [&] {
    for (int world = 0; world < n; ++world) {
      runs[world].push_back(ResultRow(envs.observations(), envs.final_observations(),
                                      envs.rewards(), envs.terminated(), envs.truncated(),
                                      envs.finished_episodes(), world));
    }
  };
  envs.Reset();
  record();
  std::vector<float> actions(static_cast<std::size_t>(n) * kActionSize);
  for (int step = 0; step < steps; ++step) {
    for (int world = 0; world < n; ++world) ActionOf(world, step, &actions[world * kActionSize]);
    envs.Step(actions.data());
    record();
  }
  return runs;
}

// The same through the pool: each world is sent its next ActionOf as soon as it comes back, until
// every world has played `steps` steps (some play more; only the first `steps` are kept).
Trajectories AsynchronousRun(AsyncEnvironmentPool& pool, int steps) {
  const int n = pool.num_envs();
  Trajectories runs(n);
  pool.Reset();
  const auto unfinished = [&] {
    return std::any_of(runs.begin(), runs.end(),
                       [steps](const auto& run) { return static_cast<int>(run.size()) <= steps; });
  };
  std::vector<float> actions(static_cast<std::size_t>(pool.batch_size()) * kActionSize);
  while (unfinished()) {
    pool.Recv();
    for (int row = 0; row < pool.batch_size(); ++row) {
      const int world = pool.env_ids()[row];
      runs[world].push_back(ResultRow(pool.observations(), pool.final_observations(),
                                      pool.rewards(), pool.terminated(), pool.truncated(),
                                      pool.finished_episodes(), row));
      ActionOf(world, static_cast<int>(runs[world].size()) - 1, &actions[row * kActionSize]);
    }
    pool.Send(actions.data(), pool.env_ids(), pool.batch_size());
  }
  for (auto& run : runs) run.resize(steps + 1);
  return runs;
}

TEST(AsyncEnvironmentPool, EveryWorldPlaysTheSynchronousTrajectory) {
  constexpr int kWorlds = 5;
  constexpr int kSteps = 40;
  BatchedEnvironment envs(ShortEpisodes(), kWorlds, 1, kSeed);
  const Trajectories expected = SynchronousRun(envs, kSteps);
  int episodes_ended = 0;
  for (const auto& run : expected) {
    for (const WorldResult& result : run) episodes_ended += result.finished_return.has_value();
  }
  ASSERT_GE(episodes_ended, kWorlds * 3);  // the auto-reset is part of what is compared
  for (const int threads : {1, 2, 3}) {
    for (const int batch : {1, 2, kWorlds}) {
      AsyncEnvironmentPool pool(ShortEpisodes(), kWorlds, batch, threads, kSeed);
      const Trajectories runs = AsynchronousRun(pool, kSteps);
      for (int world = 0; world < kWorlds; ++world) {
        for (int t = 0; t <= kSteps; ++t) {
          ASSERT_TRUE(runs[world][t] == expected[world][t])
              << "world " << world << ", entry " << t << ", " << threads << " threads, batch "
              << batch;
        }
      }
    }
  }
}

TEST(AsyncEnvironmentPool, ScenarioWorldsPlayTheSynchronousTrajectory) {
  const std::vector<Scenario> scenarios = {TrainingScenarioGenerator().Make(3),
                                           TrainingScenarioGenerator().Make(4),
                                           TrainingScenarioGenerator().Make(5)};
  BatchedEnvironment envs(ShortEpisodes(), scenarios, 1);
  AsyncEnvironmentPool pool(ShortEpisodes(), scenarios, 2, 2);
  EXPECT_EQ(AsynchronousRun(pool, 25), SynchronousRun(envs, 25));
}

// Worlds of other training scenarios (a mix: two crowded with circles, one without vessels).
TEST(AsyncEnvironmentPool, WorldsOfOtherTrainingScenariosPlayTheSynchronousTrajectory) {
  TrainingScenarioConfig crowded;
  crowded.num_static = 40;
  TrainingScenarioConfig without_vessels;
  without_vessels.num_moving = 0;
  const std::vector<TrainingScenarioConfig> worlds = {crowded, crowded, without_vessels};
  BatchedEnvironment envs(ShortEpisodes(), worlds, 1, kSeed);
  AsyncEnvironmentPool pool(ShortEpisodes(), worlds, 2, 2, kSeed);
  const Trajectories expected = SynchronousRun(envs, 25);
  EXPECT_EQ(AsynchronousRun(pool, 25), expected);
  BatchedEnvironment paper_worlds(ShortEpisodes(), 3, 1, kSeed);
  EXPECT_NE(SynchronousRun(paper_worlds, 25), expected);
}

TEST(AsyncEnvironmentPool, FullBatchIsTheSynchronousEnvironment) {
  constexpr int kWorlds = 4;
  BatchedEnvironment envs(ShortEpisodes(), kWorlds, 1, kSeed);
  AsyncEnvironmentPool pool(ShortEpisodes(), kWorlds, kWorlds, 2, kSeed);
  const std::vector<std::int32_t> all = {0, 1, 2, 3};
  const auto same_observations = [&] {
    return std::equal(envs.observations(), envs.observations() + kWorlds * kObservationSize,
                      pool.observations());
  };
  std::vector<float> actions(kWorlds * kActionSize);
  for (const std::optional<std::uint64_t> seed :
       {std::optional<std::uint64_t>(), std::optional<std::uint64_t>(),
        std::optional<std::uint64_t>(7)}) {
    envs.Reset(seed);
    pool.Reset(seed);
    pool.Recv();
    EXPECT_TRUE(std::equal(all.begin(), all.end(), pool.env_ids()));
    EXPECT_TRUE(same_observations());
    for (int step = 0; step < 20; ++step) {
      for (int world = 0; world < kWorlds; ++world) {
        ActionOf(world, step, &actions[world * kActionSize]);
      }
      envs.Step(actions.data());
      pool.Send(actions.data(), all.data(), kWorlds);
      pool.Recv();
      ASSERT_TRUE(std::equal(all.begin(), all.end(), pool.env_ids())) << "step " << step;
      ASSERT_TRUE(same_observations()) << "step " << step;
      ASSERT_TRUE(std::equal(envs.rewards(), envs.rewards() + kWorlds, pool.rewards()));
    }
  }
}

// Rounds of Recv and Send on a pool of 6 worlds in batches of 3 (every other round one world sits
// out a round, so that worlds without an action are around while the others step); returns how
// often each world came back. Fails the test if a world comes back unsent or twice for one send.
std::vector<int> ReceivedPerWorld(int threads) {
  constexpr int kWorlds = 6;
  constexpr int kBatch = 3;
  AsyncEnvironmentPool pool(EnvironmentConfig{}, kWorlds, kBatch, threads, kSeed);
  pool.Reset();
  std::set<int> stepping = {0, 1, 2, 3, 4, 5};
  std::vector<int> sent(kWorlds, 1);  // the reset counts as one
  std::vector<int> received(kWorlds, 0);
  std::set<std::int32_t> waiting;  // came back, not sent again yet
  const std::vector<float> actions(kWorlds * kActionSize, 0.5f);
  for (int round = 0; round < 300; ++round) {
    pool.Recv();
    const std::int32_t* ids = pool.env_ids();
    EXPECT_TRUE(std::is_sorted(ids, ids + kBatch));
    for (int row = 0; row < kBatch; ++row) {
      EXPECT_EQ(stepping.erase(ids[row]), 1U) << "world " << ids[row] << " came back unsent";
      ++received[ids[row]];
      waiting.insert(ids[row]);
    }
    std::vector<std::int32_t> back(waiting.begin(), waiting.end());
    if (round % 2 == 0) back.erase(back.begin());
    pool.Send(actions.data(), back.data(), static_cast<int>(back.size()));
    for (const std::int32_t world : back) {
      waiting.erase(world);
      stepping.insert(world);
      ++sent[world];
    }
  }
  for (int world = 0; world < kWorlds; ++world) {
    EXPECT_EQ(received[world], sent[world] - static_cast<int>(stepping.count(world)))
        << "world " << world << ", " << threads << " threads";
  }
  return received;
}

TEST(AsyncEnvironmentPool, EachSentWorldComesBackExactlyOnce) {
  for (const int threads : {1, 2, 3}) ReceivedPerWorld(threads);
}

// With the caller alone stepping, nothing depends on timing: no world may wait for ever while
// others come back. (With workers, a busy machine may leave a world on a descheduled worker for
// the whole test.)
TEST(AsyncEnvironmentPool, NoWorldIsLeftBehind) {
  for (const int received : ReceivedPerWorld(1)) EXPECT_GE(received, 100);
}

TEST(AsyncEnvironmentPool, RecvWithFewerWorldsSteppingThanABatchThrows) {
  AsyncEnvironmentPool pool(EnvironmentConfig{}, 4, 3, 2, kSeed);
  pool.Reset();
  pool.Recv();  // 1 world left stepping
  EXPECT_THROW(pool.Recv(), std::logic_error);
  const std::vector<float> actions(3 * kActionSize, 0.0f);
  pool.Send(actions.data(), pool.env_ids(), 2);
  pool.Recv();  // 3 were stepping
}

// The message of the std::invalid_argument `make` throws, or "" if it throws none.
std::string InvalidArgumentMessage(const std::function<void()>& make) {
  try {
    make();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(AsyncEnvironmentPool, BadArgumentsThrowNamingTheValue) {
  const EnvironmentConfig config;
  const auto pool_message = [&config](int num_envs, int batch, int threads) {
    return InvalidArgumentMessage(
        [&] { AsyncEnvironmentPool pool(config, num_envs, batch, threads, kSeed); });
  };
  EXPECT_NE(pool_message(4, 0, 1).find("batch_size 0 is outside [1, 4]"), std::string::npos);
  EXPECT_NE(pool_message(4, 5, 1).find("batch_size 5 is outside [1, 4]"), std::string::npos);
  EXPECT_NE(pool_message(4, 2, 0).find("num_threads 0"), std::string::npos);
  EXPECT_NE(pool_message(0, 1, 1).find("num_envs 0"), std::string::npos);
  EXPECT_EQ(pool_message(4, 4, 1), "");
}

TEST(AsyncEnvironmentPool, SendChecksTheWorldsAndChangesNothingWhenItThrows) {
  AsyncEnvironmentPool pool(EnvironmentConfig{}, 4, 2, 2, kSeed);
  const std::vector<float> actions(4 * kActionSize, 0.0f);
  const std::vector<std::int32_t> first = {0};
  EXPECT_THROW(pool.Send(actions.data(), first.data(), 1), std::logic_error);  // before Reset
  pool.Reset();
  pool.Recv();
  const std::int32_t back = pool.env_ids()[0];
  std::int32_t stepping = 0;  // the lowest world that has not come back
  while (stepping == pool.env_ids()[0] || stepping == pool.env_ids()[1]) ++stepping;
  const auto message = [&](std::vector<std::int32_t> ids) {
    return InvalidArgumentMessage(
        [&] { pool.Send(actions.data(), ids.data(), static_cast<int>(ids.size())); });
  };
  EXPECT_NE(message({back, 4}).find("env id 4 is outside [0, 4)"), std::string::npos);
  EXPECT_NE(message({back, -1}).find("env id -1"), std::string::npos);
  EXPECT_NE(message({back, back}).find("env id " + std::to_string(back) + " has not come back"),
            std::string::npos);
  EXPECT_NE(message({stepping}).find("has not come back"), std::string::npos);
  // The failed sends marked nothing: both worlds can still be sent, once.
  pool.Send(actions.data(), pool.env_ids(), 2);
  EXPECT_NE(message({back}).find("has not come back"), std::string::npos);
  pool.Recv();
}

// Destroys the pool on another thread; fails (instead of hanging) if that takes over 10 s.
void ExpectDestroyedPromptly(std::unique_ptr<AsyncEnvironmentPool> pool) {
  std::promise<void> destroyed;
  std::future<void> done = destroyed.get_future();
  std::thread([pool = std::move(pool), destroyed = std::move(destroyed)]() mutable {
    pool.reset();
    destroyed.set_value();
  }).detach();
  EXPECT_EQ(done.wait_for(std::chrono::seconds(10)), std::future_status::ready);
}

TEST(AsyncEnvironmentPool, DestroyedWithWorkInFlightDoesNotHang) {
  for (const int threads : {1, 2, 4}) {
    auto queued = std::make_unique<AsyncEnvironmentPool>(EnvironmentConfig{}, 16, 4, threads, 1);
    queued->Reset();  // 16 resets queued, none received
    ExpectDestroyedPromptly(std::move(queued));

    auto stepping = std::make_unique<AsyncEnvironmentPool>(EnvironmentConfig{}, 8, 2, threads, 1);
    stepping->Reset();
    const std::vector<float> actions(2 * kActionSize, 1.0f);
    for (int round = 0; round < 20; ++round) {
      stepping->Recv();
      stepping->Send(actions.data(), stepping->env_ids(), 2);
    }
    ExpectDestroyedPromptly(std::move(stepping));
  }
  ExpectDestroyedPromptly(std::make_unique<AsyncEnvironmentPool>(EnvironmentConfig{}, 3, 1, 2, 1));
}

// With one-step episodes every step moves a world to its next episode, so whether Reset played
// the steps in flight shows in the episode it starts; results in flight must not come back.
TEST(AsyncEnvironmentPool, ResetPlaysTheStepsInFlightAndDropsTheirResults) {
  constexpr int kWorlds = 4;
  EnvironmentConfig config;
  config.max_steps = 1;
  BatchedEnvironment envs(config, kWorlds, 1, kSeed);
  const std::vector<float> actions(kWorlds * kActionSize, 0.2f);
  envs.Reset();
  envs.Step(actions.data());
  envs.Reset();
  for (const int threads : {1, 2}) {  // with 1, the steps are still queued when Reset comes
    AsyncEnvironmentPool pool(config, kWorlds, kWorlds, threads, kSeed);
    pool.Reset();
    pool.Recv();
    pool.Send(actions.data(), pool.env_ids(), kWorlds);
    pool.Reset();
    pool.Recv();
    EXPECT_TRUE(std::equal(envs.observations(), envs.observations() + kWorlds * kObservationSize,
                           pool.observations()))
        << threads << " threads";
    EXPECT_THROW(pool.Recv(), std::logic_error);  // nothing else is on its way
  }
}

}  // namespace
}  // namespace colav

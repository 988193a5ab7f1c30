#include "eval/episode_runner.h"

#include <algorithm>
#include <atomic>
#include <iterator>
#include <memory>

#include "env/environment.h"
#include "env/scenario_file.h"
#include "eval/replay/replay_recorder.h"
#include "src/threads/thread_pool.h"

namespace colav {
namespace {

// One policy's run through one episode.
struct Lane {
  std::unique_ptr<Environment> env;
  float* observation = nullptr;  // row of the policy's observation batch
  bool done = false;
  EpisodeOutcome outcome;
  std::optional<ReplayRecorder> recorder;  // when replays are recorded
};

void StepLane(Lane& lane, const float* action) {
  const double action_values[kActionSize] = {action[0], action[1]};
  const StepResult result = lane.env->Step(action_values, lane.observation);
  lane.outcome.positions.emplace_back(lane.env->world().vessel().head<2>());
  lane.outcome.cumulative_rewards.push_back(lane.outcome.cumulative_rewards.back() + result.reward);
  lane.outcome.actions.push_back({action[0], action[1]});
  if (lane.recorder) lane.recorder->Record(lane.env->world(), action_values, result);
  if (result.episode) {
    lane.outcome.metrics = *result.episode;
    lane.done = true;
    if (lane.recorder) lane.outcome.replay = lane.recorder->TakeReplay();
  }
}

// The actions for the given rows of a policy's observation batch; a recurrent policy reads the
// same rows of `states` and writes their next states back. At least two rows go through the
// policy: for a single row LibTorch takes a matrix-vector path whose rounding differs, and an
// episode's result would depend on whether it happened to run last.
torch::Tensor ActOnRows(Policy& policy, const torch::Tensor& observations, torch::Tensor& states,
                        std::vector<std::int64_t> rows) {
  const std::int64_t count = static_cast<std::int64_t>(rows.size());
  if (count == 1) rows.push_back(rows.front());
  const torch::Tensor index = torch::tensor(rows);
  const torch::Tensor batch = observations.index_select(0, index);
  if (!policy.recurrent()) return policy.Act(batch).slice(0, 0, count).contiguous();
  torch::Tensor row_states = states.index_select(0, index);
  const torch::Tensor actions = policy.Step(batch, row_states);
  states.index_copy_(0, index.slice(0, 0, count), row_states.slice(0, 0, count));
  return actions.slice(0, 0, count).contiguous();
}

// Lanes (worlds) alive at once, at most: each world holds its path's dense polyline and its
// obstacles (a few hundred kB), so 53 models x 1,000 scenarios at once would stream ~10 GB through
// memory every time step (measured: 4.5 episodes/s instead of 200).
constexpr int kMaxLanes = 4096;

// Policies [first, last) on every episode, in lock step; `finished_before` episodes of other
// blocks are already done (for the progress callback).
std::vector<std::vector<EpisodeOutcome>> RunModelBlock(
    std::vector<Policy>& policies, int first, int last,
    const std::vector<EvaluationEpisode>& episodes, const EnvironmentConfig& config,
    ThreadPool& pool, int finished_before, int total,
    const std::function<void(int finished, int total)>& on_episode_done, bool record_replays) {
  const int num_models = last - first;
  const int num_episodes = static_cast<int>(episodes.size());
  std::vector<torch::Tensor> observations;
  std::vector<torch::Tensor> states(num_models);  // a recurrent policy's, row e for episode e
  std::vector<Lane> lanes(static_cast<std::size_t>(num_models) * num_episodes);
  for (int m = 0; m < num_models; ++m) {
    const EnvironmentConfig policy_config = WithObservationSettings(
        config, policies[first + m].SettingsOr(ObservationSettingsOf(config)));
    const int observation_size = ObservationSize(policy_config);
    observations.push_back(torch::zeros({num_episodes, observation_size}));
    if (policies[first + m].recurrent()) {
      states[m] = policies[first + m].InitialStates(num_episodes);
    }
    for (int e = 0; e < num_episodes; ++e) {
      Lane& lane = lanes[m * num_episodes + e];
      const EvaluationEpisode& episode = episodes[e];
      lane.env = std::make_unique<Environment>(
          policy_config, std::make_shared<FixedScenarioSource>(episode.scenario));
      lane.observation = observations[m].data_ptr<float>() + e * observation_size;
      lane.env->Reset(episode.seed.value_or(0), lane.observation);
      lane.outcome.positions.emplace_back(lane.env->world().vessel().head<2>());
      lane.outcome.cumulative_rewards.push_back(0.0);
      if (record_replays) {
        lane.recorder.emplace(lane.env->world(), episode.name, policies[first + m].name());
      }
    }
  }
  int finished = 0;
  while (finished < static_cast<int>(lanes.size())) {
    // Only unfinished episodes are forwarded: most end long before the slowest one.
    std::vector<torch::Tensor> actions(num_models);
    std::vector<std::pair<Lane*, const float*>> work;  // lane, its action
    for (int m = 0; m < num_models; ++m) {
      std::vector<std::int64_t> active;
      for (int e = 0; e < num_episodes; ++e) {
        if (!lanes[m * num_episodes + e].done) active.push_back(e);
      }
      if (active.empty()) continue;
      actions[m] = ActOnRows(policies[first + m], observations[m], states[m], active);
      for (std::size_t j = 0; j < active.size(); ++j) {
        work.emplace_back(&lanes[m * num_episodes + active[j]],
                          actions[m].data_ptr<float>() + j * kActionSize);
      }
    }
    std::atomic<int> newly_finished{0};
    pool.ParallelFor(static_cast<int>(work.size()), [&](int i) {
      StepLane(*work[i].first, work[i].second);
      if (work[i].first->done) ++newly_finished;
    });
    finished += newly_finished;
    if (newly_finished > 0 && on_episode_done) on_episode_done(finished_before + finished, total);
  }
  std::vector<std::vector<EpisodeOutcome>> outcomes(num_models);
  for (int m = 0; m < num_models; ++m) {
    for (int e = 0; e < num_episodes; ++e) {
      outcomes[m].push_back(std::move(lanes[m * num_episodes + e].outcome));
    }
  }
  return outcomes;
}

}  // namespace

std::vector<std::vector<EpisodeOutcome>> RunEpisodes(
    std::vector<Policy>& policies, const std::vector<EvaluationEpisode>& episodes,
    const EnvironmentConfig& config, int num_threads,
    const std::function<void(int finished, int total)>& on_episode_done, bool record_replays) {
  const int num_models = static_cast<int>(policies.size());
  const int num_episodes = static_cast<int>(episodes.size());
  const int total = num_models * num_episodes;
  // A model's episodes do not depend on the other models (each forward sees its own rows), so
  // running the models in blocks gives the same outcomes.
  const int block = std::max(1, kMaxLanes / std::max(1, num_episodes));
  ThreadPool pool(num_threads);
  std::vector<std::vector<EpisodeOutcome>> outcomes;
  for (int first = 0; first < num_models; first += block) {
    const int last = std::min(num_models, first + block);
    auto block_outcomes =
        RunModelBlock(policies, first, last, episodes, config, pool, first * num_episodes, total,
                      on_episode_done, record_replays);
    std::move(block_outcomes.begin(), block_outcomes.end(), std::back_inserter(outcomes));
  }
  return outcomes;
}

}  // namespace colav

// Evaluation runs: deterministic, paired (every model on the same scenarios), and each episode's
// result independent of the rest of the batch.
#include "eval/episode_runner.h"

#include <gtest/gtest.h>

#include "env/environment.h"
#include "env/path.h"
#include "env/scenario_file.h"
#include "eval/episode_table.h"
#include "src/seeding.h"
#include "tests/eval/test_policies.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
namespace tp = testing_policies;

EnvironmentConfig ShortTestEpisodes() {
  EnvironmentConfig config;
  config.test_mode = true;
  config.max_steps = 300;
  return config;
}

std::string Table(std::vector<Policy>& policies, const std::vector<EvaluationEpisode>& episodes,
                  int threads) {
  std::vector<std::string> names;
  for (const Policy& policy : policies) names.push_back(policy.name());
  return EpisodeTable(names, episodes,
                      RunEpisodes(policies, episodes, ShortTestEpisodes(), threads));
}

class EpisodeRunnerTest : public ::testing::Test {
 protected:
  Policy Reactive(std::uint64_t seed, const std::string& name) {
    return Policy(tp::SavePolicy(tp::ReactivePolicy(seed), folder_ / (name + ".pt")), name);
  }
  Policy RecurrentReactive(std::uint64_t seed, const std::string& name) {
    return Policy(tp::SavePolicy(tp::RecurrentReactivePolicy(seed), folder_ / (name + ".pt")),
                  name);
  }
  TemporaryFolder folder_;
};

TEST_F(EpisodeRunnerTest, TestScenariosComeFromAFixedSeedList) {
  const auto five = TestEpisodes(7, 5);
  const auto three = TestEpisodes(7, 3);
  ASSERT_EQ(five.size(), 5U);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(three[k].name, five[k].name);
    EXPECT_EQ(*three[k].seed, DeriveSeed(7, "test-scenario", k));
    EXPECT_EQ(three[k].scenario.vessel_position, five[k].scenario.vessel_position);
  }
  EXPECT_EQ(five[4].name, "test-004");
  EXPECT_NE(*TestEpisodes(8, 1)[0].seed, *five[0].seed);
}

TEST_F(EpisodeRunnerTest, SamePolicySameSeedsGiveTheSameTable) {
  const auto episodes = TestEpisodes(3, 4);
  std::vector<Policy> first = {Reactive(1, "a")};
  std::vector<Policy> second = {Reactive(1, "a")};
  const std::string table = Table(first, episodes, 2);
  EXPECT_EQ(table, Table(second, episodes, 1));
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 5);
  EXPECT_EQ(table.substr(0, table.find('\n')), EpisodeTableHeader());
}

TEST_F(EpisodeRunnerTest, AModelsRowsDoNotDependOnTheOtherModels) {
  const auto episodes = TestEpisodes(3, 4);
  std::vector<Policy> alone = {Reactive(1, "a")};
  std::vector<Policy> together = {Reactive(2, "b"), Reactive(1, "a")};
  const std::string alone_table = Table(alone, episodes, 2);
  const std::string together_table = Table(together, episodes, 2);
  const std::string a_rows = alone_table.substr(alone_table.find('\n') + 1);
  EXPECT_NE(together_table.find(a_rows), std::string::npos) << together_table;
  EXPECT_NE(together_table.find("\nb,test-000,"), std::string::npos);
}

TEST_F(EpisodeRunnerTest, AnEpisodeDoesNotDependOnTheOtherEpisodes) {
  // Episode 2 alone (forwarded as two rows), and in a batch whose size shrinks as the others end.
  const auto episodes = TestEpisodes(3, 6);
  std::vector<Policy> policies = {Reactive(1, "a")};
  const std::string batch_table = Table(policies, episodes, 2);
  const std::string alone_table = Table(policies, {episodes[2]}, 1);
  const std::string alone_row = alone_table.substr(alone_table.find('\n') + 1);
  EXPECT_NE(batch_table.find("\n" + alone_row), std::string::npos) << batch_table << alone_row;
}

TEST_F(EpisodeRunnerTest, RecordsTheTrackAndTheCumulativeReward) {
  std::vector<Policy> policies = {Reactive(1, "a")};
  const auto episodes = TestEpisodes(3, 2);
  const auto outcomes = RunEpisodes(policies, episodes, ShortTestEpisodes(), 2);
  for (const EpisodeOutcome& outcome : outcomes[0]) {
    ASSERT_EQ(outcome.positions.size(), static_cast<std::size_t>(outcome.metrics.steps) + 1);
    ASSERT_EQ(outcome.cumulative_rewards.size(), outcome.positions.size());
    EXPECT_DOUBLE_EQ(outcome.cumulative_rewards.front(), 0.0);
    EXPECT_NEAR(outcome.cumulative_rewards.back(), outcome.metrics.cumulative_reward, 1e-9);
    EXPECT_GT(outcome.metrics.path_length, 250.0);
  }
  EXPECT_EQ(outcomes[0][0].positions.front(), episodes[0].scenario.vessel_position);
}

using Actions = std::vector<std::array<float, kActionSize>>;

// `episode` stepped by hand with `policy`, its state carried from InitialStates: the episode's row
// goes through step twice, as the runner never forwards a single row.
Actions RecurrentActionsByHand(Policy& policy, const EvaluationEpisode& episode) {
  Environment env(ShortTestEpisodes(), std::make_shared<FixedScenarioSource>(episode.scenario));
  torch::Tensor observation = torch::zeros({1, ObservationSize(ShortTestEpisodes())});
  env.Reset(episode.seed.value_or(0), observation.data_ptr<float>());
  torch::Tensor states = policy.InitialStates(2);
  Actions actions;
  for (bool done = false; !done;) {
    const torch::Tensor action = policy.Step(observation.repeat({2, 1}), states)[0];
    actions.push_back({action[0].item<float>(), action[1].item<float>()});
    const double values[kActionSize] = {actions.back()[0], actions.back()[1]};
    done = env.Step(values, observation.data_ptr<float>()).episode.has_value();
  }
  return actions;
}

void ExpectSameActions(const Actions& actual, const Actions& expected, const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  for (std::size_t k = 0; k < actual.size(); ++k) {
    ASSERT_EQ(actual[k], expected[k]) << what << ", step " << k;
  }
}

// Each episode keeps its own state, from zero at its start, whatever the other rows do: the
// batch's actions are those of the episode alone and those of a hand-carried state, also after
// an episode has ended and the rows of the later ones have moved up.
TEST_F(EpisodeRunnerTest, ARecurrentPolicyKeepsOneStatePerEpisode) {
  const auto episodes = TestEpisodes(3, 5);
  std::vector<Policy> policies = {RecurrentReactive(1, "r")};
  const auto batch = RunEpisodes(policies, episodes, ShortTestEpisodes(), 2);
  ASSERT_LT(batch[0][3].metrics.steps, batch[0][4].metrics.steps) << "the batch must shrink";
  const auto alone = RunEpisodes(policies, {episodes[4]}, ShortTestEpisodes(), 1);
  ExpectSameActions(alone[0][0].actions, batch[0][4].actions, "episode 4 alone");
  for (std::size_t e = 0; e < episodes.size(); ++e) {
    ExpectSameActions(batch[0][e].actions, RecurrentActionsByHand(policies[0], episodes[e]),
                      "episode " + std::to_string(e) + " by hand");
  }
}

// The collision analysis replays an episode from its scenario and recorded actions alone.
TEST_F(EpisodeRunnerTest, RecordedActionsReplayTheEpisode) {
  std::vector<Policy> policies = {Reactive(1, "a")};
  const auto episodes = TestEpisodes(3, 2);
  const auto outcomes = RunEpisodes(policies, episodes, ShortTestEpisodes(), 2);
  for (std::size_t e = 0; e < episodes.size(); ++e) {
    const EpisodeOutcome& outcome = outcomes[0][e];
    ASSERT_EQ(outcome.actions.size(), static_cast<std::size_t>(outcome.metrics.steps));
    Environment env(ShortTestEpisodes(),
                    std::make_shared<FixedScenarioSource>(episodes[e].scenario));
    std::vector<float> observation(ObservationSize(ShortTestEpisodes()));
    env.Reset(episodes[e].seed.value_or(0), observation.data());
    for (std::size_t k = 0; k < outcome.actions.size(); ++k) {
      const double action[kActionSize] = {outcome.actions[k][0], outcome.actions[k][1]};
      env.Step(action, observation.data());
      ASSERT_EQ(env.world().vessel().head<2>(), outcome.positions[k + 1]) << "step " << k;
    }
  }
}

TEST_F(EpisodeRunnerTest, PerturbedStartsAreReproducibleAndNearThePathStart) {
  const EvaluationEpisode episode = TestEpisodes(3, 1)[0];
  const EvaluationEpisode a = WithPerturbedStart(episode, 3, 1);
  const EvaluationEpisode b = WithPerturbedStart(episode, 3, 2);
  EXPECT_EQ(a.name, "test-000-start1");
  EXPECT_EQ(a.scenario.vessel_position, WithPerturbedStart(episode, 3, 1).scenario.vessel_position);
  EXPECT_NE(a.scenario.vessel_position, b.scenario.vessel_position);
  EXPECT_EQ(a.scenario.dynamic_obstacles.size(), episode.scenario.dynamic_obstacles.size());
  // Within the training environment's +-25 m box around the path start.
  const Eigen::Vector2d path_start = Path(episode.scenario.waypoints).start();
  EXPECT_LE((a.scenario.vessel_position - path_start).cwiseAbs().maxCoeff(), 25.0);
  EXPECT_LE((b.scenario.vessel_position - path_start).cwiseAbs().maxCoeff(), 25.0);
}

}  // namespace
}  // namespace colav

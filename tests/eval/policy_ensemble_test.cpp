// The ensemble policy file (eval/policy_ensemble.h): what its methods compute from its members'
// and what it refuses. Python's view of the same files: tests/python/test_ensemble_policy.py.
#include "eval/policy_ensemble.h"

#include <gtest/gtest.h>

#include "env/environment_spec.h"
#include "env/range_finder.h"
#include "models/observation_settings_record.h"
#include "tests/eval/test_policies.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;
namespace tp = testing_policies;

// `module` with the default observation settings recorded, saved as `path`.
std::filesystem::path SaveMember(torch::jit::Module module, const std::filesystem::path& path) {
  RecordObservationSettings(module, ObservationSettings{});
  return tp::SavePolicy(module, path);
}

// Always `action` (a TorchScript list literal), whatever it observes.
torch::jit::Module ConstantPolicy(const std::string& action) {
  return tp::ScriptedModule(
      "def forward(self, obs: Tensor) -> Tensor:\n"
      "    return torch.tensor([" +
      action + "]).repeat(obs.size(0), 1)\n");
}

// A memory of two values that starts at ones and counts the steps; it steers by its count.
torch::jit::Module CountingPolicy() {
  return tp::RecurrentModule(R"(
def initial_state(self, batch: int) -> Tensor:
    return torch.ones([batch, 2])
def step(self, obs: Tensor, state: Tensor) -> Tuple[Tensor, Tensor]:
    next_state = state + 1.0
    return torch.cat([torch.zeros_like(obs[:, 0:1]), 0.1 * next_state[:, 0:1]], 1), next_state
)",
                             2);
}

TEST(EnsemblePolicy, AveragesTheActionsEachMemberWouldBeEvaluatedWith) {
  const TemporaryFolder folder;
  // evaluate clips the first member's thrust of 3 to 1: the ensemble averages 1 and -1, not 3.
  WriteEnsemblePolicy({SaveMember(ConstantPolicy("3.0, 0.0"), folder / "a.pt"),
                       SaveMember(ConstantPolicy("-1.0, 0.5"), folder / "b.pt")},
                      folder / "ensemble.pt", {});
  Policy ensemble(folder / "ensemble.pt", "ensemble");
  EXPECT_FALSE(ensemble.recurrent());
  EXPECT_EQ(ensemble.settings_origin(), "recorded in the file");
  const torch::Tensor actions = ensemble.Act(torch::zeros({3, 186}));
  EXPECT_TRUE(torch::allclose(actions, torch::tensor({0.0F, 0.25F}).repeat({3, 1})));
}

TEST(EnsemblePolicy, StartsAndStepsEachMemoryInItsOwnColumns) {
  const TemporaryFolder folder;
  WriteEnsemblePolicy({SaveMember(ConstantPolicy("1.0, -0.5"), folder / "plain.pt"),
                       SaveMember(CountingPolicy(), folder / "counting.pt"),
                       SaveMember(tp::RecurrentReactivePolicy(4), folder / "reactive.pt")},
                      folder / "ensemble.pt", {});
  Policy ensemble(folder / "ensemble.pt", "ensemble");
  Policy counting(folder / "counting.pt", "counting");
  Policy reactive(folder / "reactive.pt", "reactive");
  ASSERT_EQ(ensemble.recurrent_size(), 5);
  torch::Tensor states = ensemble.InitialStates(2);
  torch::Tensor counting_states = counting.InitialStates(2);
  torch::Tensor reactive_states = reactive.InitialStates(2);
  EXPECT_TRUE(torch::equal(states, torch::cat({counting_states, reactive_states}, 1)));
  torch::manual_seed(5);
  for (int step = 0; step < 3; ++step) {  // a misplaced column shows once the memories differ
    const torch::Tensor obs = torch::rand({2, 186});
    const torch::Tensor expected =
        (torch::tensor({1.0F, -0.5F}).repeat({2, 1}) + counting.Step(obs, counting_states) +
         reactive.Step(obs, reactive_states)) /
        3.0;
    EXPECT_TRUE(torch::allclose(ensemble.Step(obs, states), expected)) << "step " << step;
    EXPECT_TRUE(torch::equal(states, torch::cat({counting_states, reactive_states}, 1)));
  }
}

// Observations [3, 186] whose nearest returns lie at `ranges` metres (150: none), one per row.
torch::Tensor ObservationsWithNearestReturns(const std::vector<double>& ranges) {
  torch::Tensor obs = torch::zeros({static_cast<std::int64_t>(ranges.size()), kObservationSize});
  for (std::size_t row = 0; row < ranges.size(); ++row) {
    const double closeness = Closeness(ranges[row], ObservationSettings{}.closeness);
    obs[static_cast<std::int64_t>(row)][kNavigationSize + 17] = closeness;        // any ray
    obs[static_cast<std::int64_t>(row)][kNavigationSize + 90] = closeness / 2.0;  // a farther one
  }
  return obs;
}

TEST(EnsemblePolicy, TheFirstOfTwoSteersNearObstaclesAndBothMemoriesStep) {
  const TemporaryFolder folder;
  WriteEnsemblePolicy({SaveMember(ConstantPolicy("1.0, -0.5"), folder / "near.pt"),
                       SaveMember(CountingPolicy(), folder / "far.pt")},
                      folder / "ensemble.pt", {30.0, std::nullopt});
  Policy ensemble(folder / "ensemble.pt", "ensemble");
  Policy far(folder / "far.pt", "far");
  torch::Tensor states = ensemble.InitialStates(3);
  torch::Tensor far_states = far.InitialStates(3);
  for (int step = 0; step < 2; ++step) {  // the far member's memory counts every step
    const torch::Tensor obs = ObservationsWithNearestReturns({29.0, 31.0, 150.0});
    const torch::Tensor far_actions = far.Step(obs, far_states);
    const torch::Tensor actions = ensemble.Step(obs, states);
    EXPECT_TRUE(torch::equal(actions[0], torch::tensor({1.0F, -0.5F}))) << step;
    EXPECT_TRUE(torch::equal(actions.slice(0, 1), far_actions.slice(0, 1))) << step;
    EXPECT_TRUE(torch::equal(states, far_states)) << step;
  }
}

// Observations [3, 186] of a vessel at surge speeds `u` (m/s) and heading errors `heading_error`
// (rad), one per row, with no obstacle in range.
torch::Tensor ObservationsUnderWay(const std::vector<float>& u,
                                   const std::vector<float>& heading_error) {
  torch::Tensor obs = torch::zeros({static_cast<std::int64_t>(u.size()), kObservationSize});
  obs.select(1, 0) = torch::tensor(u);
  obs.select(1, 4) = torch::tensor(heading_error);
  return obs;
}

TEST(EnsemblePolicy, TheSecondOfTwoSteersFromTheStepTheVesselStallsOn) {
  const TemporaryFolder folder;
  // Pace averaged over 2 steps: pace' = pace / 2 + u cos(heading error) / 2, from 0.5 m/s.
  WriteEnsemblePolicy({SaveMember(ConstantPolicy("1.0, 0.0"), folder / "first.pt"),
                       SaveMember(ConstantPolicy("-1.0, 0.5"), folder / "relief.pt")},
                      folder / "ensemble.pt", {std::nullopt, StallRule{0.3, 2}});
  Policy ensemble(folder / "ensemble.pt", "ensemble");
  ASSERT_EQ(ensemble.recurrent_size(), 2);  // memoryless members: the rule's columns alone
  torch::Tensor states = ensemble.InitialStates(3);
  EXPECT_TRUE(torch::equal(states, torch::tensor({0.5F, 0.0F}).repeat({3, 1})));
  const torch::Tensor first = torch::tensor({1.0F, 0.0F});
  const torch::Tensor relief = torch::tensor({-1.0F, 0.5F});
  // Row 0 cruises (pace 0.5); row 1 runs away from the look-ahead point at 1 m/s (pace -0.25 at
  // once); row 2 slows to 0.2 m/s (pace 0.35, then 0.275 < 0.3: a stall, which restarts the
  // average at 0.5), then cruises at 0.5 m/s, but the relief keeps the helm for the rest of the
  // episode.
  const std::vector<std::vector<torch::Tensor>> expected = {
      {first, first, first}, {relief, relief, relief}, {first, relief, relief}};
  const std::vector<float> heading_errors = {0.0F, 3.14159265F, 0.0F};
  const std::vector<std::vector<float>> speeds = {
      {0.5F, 1.0F, 0.2F}, {0.5F, 1.0F, 0.2F}, {0.5F, 1.0F, 0.5F}};
  for (int step = 0; step < 3; ++step) {
    const torch::Tensor actions =
        ensemble.Step(ObservationsUnderWay(speeds[step], heading_errors), states);
    for (int row = 0; row < 3; ++row) {
      EXPECT_TRUE(torch::equal(actions[row], expected[row][step]))
          << "row " << row << " step " << step;
    }
  }
  EXPECT_NEAR(states[2][0].item<float>(), 0.5F, 1e-6F);
  EXPECT_TRUE(torch::equal(states.select(1, 1), torch::tensor({0.0F, 1.0F, 1.0F})));  // stalls
}

TEST(EnsemblePolicy, AThirdMemberSteersFromTheSecondStallOn) {
  const TemporaryFolder folder;
  // Pace averaged over 2 steps from 0.5 m/s, restarted at 0.5 by each stall (pace < 0.3).
  WriteEnsemblePolicy({SaveMember(ConstantPolicy("1.0, 0.0"), folder / "first.pt"),
                       SaveMember(ConstantPolicy("-1.0, 0.5"), folder / "relief.pt"),
                       SaveMember(ConstantPolicy("0.25, -1.0"), folder / "rescue.pt")},
                      folder / "ensemble.pt", {std::nullopt, StallRule{0.3, 2}});
  Policy ensemble(folder / "ensemble.pt", "ensemble");
  torch::Tensor states = ensemble.InitialStates(3);
  const torch::Tensor first = torch::tensor({1.0F, 0.0F});
  const torch::Tensor relief = torch::tensor({-1.0F, 0.5F});
  const torch::Tensor rescue = torch::tensor({0.25F, -1.0F});
  // Row 0 cruises at 0.5 m/s; row 1 crawls at 0.2 m/s (pace 0.35, 0.275: a stall; again 0.35,
  // 0.275: the second); row 2 runs away from the look-ahead point (pace -0.25: a stall at every
  // step, the count held at the two reliefs).
  const std::vector<std::vector<torch::Tensor>> expected = {
      {first, first, first, first, first},
      {first, relief, relief, rescue, rescue},
      {relief, rescue, rescue, rescue, rescue}};
  for (int step = 0; step < 5; ++step) {
    const torch::Tensor actions =
        ensemble.Step(ObservationsUnderWay({0.5F, 0.2F, 1.0F}, {0.0F, 0.0F, 3.14159265F}), states);
    for (int row = 0; row < 3; ++row) {
      EXPECT_TRUE(torch::equal(actions[row], expected[row][step]))
          << "row " << row << " step " << step;
    }
  }
  EXPECT_TRUE(torch::equal(states.select(1, 1), torch::tensor({0.0F, 2.0F, 2.0F})));
}

TEST(EnsemblePolicy, TheSecondKeepsTheHelmNearObstaclesOnceStalled) {
  const TemporaryFolder folder;
  WriteEnsemblePolicy({SaveMember(ConstantPolicy("1.0, 0.0"), folder / "near.pt"),
                       SaveMember(ConstantPolicy("-1.0, 0.5"), folder / "far.pt")},
                      folder / "ensemble.pt", {30.0, StallRule{0.3, 2}});
  Policy ensemble(folder / "ensemble.pt", "ensemble");
  torch::Tensor states = ensemble.InitialStates(3);
  torch::Tensor obs = ObservationsWithNearestReturns({20.0, 100.0, 20.0});
  obs.slice(1, 0, kNavigationSize) =
      ObservationsUnderWay({0.5F, 0.5F, 1.0F}, {0.0F, 0.0F, 3.14159265F})
          .slice(1, 0, kNavigationSize);
  const torch::Tensor actions = ensemble.Step(obs, states);  // near; far; near but stalled
  EXPECT_TRUE(
      torch::equal(actions, torch::tensor({1.0F, 0.0F, -1.0F, 0.5F, -1.0F, 0.5F}).view({3, 2})));
}

// With the range rule too, the third member is a relief only: it steers from the second stall on,
// near obstacles or not.
TEST(EnsemblePolicy, WithTheRangeRuleTheThirdMemberStillWaitsForTheSecondStall) {
  const TemporaryFolder folder;
  WriteEnsemblePolicy({SaveMember(ConstantPolicy("1.0, 0.0"), folder / "near.pt"),
                       SaveMember(ConstantPolicy("-1.0, 0.5"), folder / "far.pt"),
                       SaveMember(ConstantPolicy("0.25, -1.0"), folder / "rescue.pt")},
                      folder / "ensemble.pt", {30.0, StallRule{0.3, 2}});
  Policy ensemble(folder / "ensemble.pt", "ensemble");
  torch::Tensor states = ensemble.InitialStates(4);
  torch::Tensor obs = ObservationsWithNearestReturns({20.0, 100.0, 20.0, 100.0});
  // Rows 0 and 1 cruise; rows 2 and 3 run away from the look-ahead point: a stall at each step.
  obs.slice(1, 0, kNavigationSize) =
      ObservationsUnderWay({0.5F, 0.5F, 1.0F, 1.0F}, {0.0F, 0.0F, 3.14159265F, 3.14159265F})
          .slice(1, 0, kNavigationSize);
  const torch::Tensor first_step = ensemble.Step(obs, states);  // near; far; first stall twice
  EXPECT_TRUE(torch::equal(
      first_step, torch::tensor({1.0F, 0.0F, -1.0F, 0.5F, -1.0F, 0.5F, -1.0F, 0.5F}).view({4, 2})));
  const torch::Tensor second_step = ensemble.Step(obs, states);  // the second stall: the rescue
  EXPECT_TRUE(torch::equal(
      second_step,
      torch::tensor({1.0F, 0.0F, -1.0F, 0.5F, 0.25F, -1.0F, 0.25F, -1.0F}).view({4, 2})));
}

TEST(EnsemblePolicy, RefusesARuleItCannotApply) {
  EXPECT_EQ(UserErrorMessage([] {
              CheckEnsemble(3, {30.0, std::nullopt});
            }),
            "--near-within: takes two policies (the one near obstacles, the other), or more with "
            "--stall-pace (the later ones relieve at the second stall and after), got 3");
  EXPECT_NO_THROW(CheckEnsemble(3, {30.0, StallRule{}}));
  EXPECT_NO_THROW(CheckEnsemble(4, {std::nullopt, StallRule{}}));
  EXPECT_EQ(UserErrorMessage([] {
              CheckEnsemble(2, {150.0, std::nullopt});
            }),
            "--near-within 150: expects metres in (0, 150)");
  EXPECT_EQ(UserErrorMessage([] { CheckEnsemble(1, {}); }),
            "an ensemble needs at least two policies");
  EXPECT_EQ(UserErrorMessage([] {
              CheckEnsemble(2, {std::nullopt, StallRule{0.5, 200}});
            }),
            "--stall-pace 0.5: expects m/s in (0, 0.5)");
  EXPECT_EQ(UserErrorMessage([] {
              CheckEnsemble(2, {std::nullopt, StallRule{0.1, 0}});
            }),
            "--stall-steps 0: expects at least 1");
}

TEST(EnsemblePolicy, RefusesToWriteOverAMember) {
  const TemporaryFolder folder;
  const std::filesystem::path a = SaveMember(ConstantPolicy("1.0, 0.0"), folder / "a.pt");
  const std::filesystem::path b = SaveMember(ConstantPolicy("0.0, 1.0"), folder / "b.pt");
  const std::string before = testing_util::ReadFile(b);
  EXPECT_EQ(UserErrorMessage([&] {
              WriteEnsemblePolicy({a, b}, folder / "." / "b.pt", {});
            }),
            "--out " + (folder / "." / "b.pt").string() + ": is one of the members");
  EXPECT_EQ(testing_util::ReadFile(b), before);
}

}  // namespace
}  // namespace colav

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
                      folder / "ensemble.pt", {30.0});
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

TEST(EnsemblePolicy, RefusesARuleItCannotApply) {
  EXPECT_EQ(UserErrorMessage([] { CheckEnsemble(3, {30.0}); }),
            "--near-within: takes exactly two policies (the one near obstacles, the other), got 3");
  EXPECT_EQ(UserErrorMessage([] { CheckEnsemble(2, {150.0}); }),
            "--near-within 150: expects metres in (0, 150)");
  EXPECT_EQ(UserErrorMessage([] { CheckEnsemble(1, {}); }),
            "an ensemble needs at least two policies");
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

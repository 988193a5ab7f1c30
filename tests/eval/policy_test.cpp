// Loading policy files: the contract checks and their one-line errors.
#include "eval/policy.h"

#include <gtest/gtest.h>

#include "models/actor_critic.h"
#include "models/policy_export.h"
#include "tests/eval/test_policies.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;
namespace tp = testing_policies;

std::string LoadError(const std::filesystem::path& path) {
  return UserErrorMessage([&] { Policy policy(path, "p"); });
}

void ExpectOneLineNamingFile(const std::string& message, const std::filesystem::path& path,
                             const std::string& reason) {
  EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0U) << message;
  EXPECT_NE(message.find(reason), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(Policy, ActsWithClippedDeterministicActions) {
  const TemporaryFolder folder;
  Policy policy(tp::SavePolicy(tp::ConstantThrustPolicy(), folder / "policy.pt"), "constant");
  EXPECT_EQ(policy.name(), "constant");
  EXPECT_FALSE(policy.recurrent());
  const torch::Tensor actions = policy.Act(torch::zeros({5, 186}));
  ASSERT_EQ(actions.sizes(), (std::vector<std::int64_t>{5, 2}));
  EXPECT_TRUE(torch::equal(actions.select(1, 0), torch::ones({5})));
  EXPECT_TRUE(torch::equal(actions.select(1, 1), torch::zeros({5})));
  // A large observation drives tanh to the bound, never beyond.
  Policy reactive(tp::SavePolicy(tp::ReactivePolicy(1), folder / "reactive.pt"), "reactive");
  const torch::Tensor bounded = reactive.Act(1e3 * torch::randn({64, 186}));
  EXPECT_LE(bounded.abs().max().item<float>(), 1.0F);
}

TEST(Policy, MissingFile) {
  const TemporaryFolder folder;
  ExpectOneLineNamingFile(LoadError(folder / "absent.pt"), folder / "absent.pt",
                          "no such policy file");
}

TEST(Policy, CorruptFile) {
  const TemporaryFolder folder;
  testing_util::WriteFile(folder / "corrupt.pt", "this is not a zip archive of TorchScript");
  ExpectOneLineNamingFile(LoadError(folder / "corrupt.pt"), folder / "corrupt.pt",
                          "not a TorchScript policy");
  // A truncated real policy file.
  tp::SavePolicy(tp::ConstantThrustPolicy(), folder / "whole.pt");
  const std::string whole = testing_util::ReadFile(folder / "whole.pt");
  testing_util::WriteFile(folder / "truncated.pt", whole.substr(0, whole.size() / 2));
  ExpectOneLineNamingFile(LoadError(folder / "truncated.pt"), folder / "truncated.pt",
                          "not a TorchScript policy");
}

TEST(Policy, WrongObservationSize) {
  const TemporaryFolder folder;
  const auto path = tp::SavePolicy(tp::WrongObservationSizePolicy(), folder / "small.pt");
  const std::string message = LoadError(path);
  ExpectOneLineNamingFile(message, path, "forward(obs [1, 186]) failed");
  // The interpreter's reason, not its traceback banner.
  EXPECT_NE(message.find("186"), std::string::npos) << message;
  EXPECT_NE(message.find("180"), std::string::npos) << message;
}

TEST(Policy, WrongActionSize) {
  const TemporaryFolder folder;
  const auto path = tp::SavePolicy(tp::WrongActionSizePolicy(), folder / "three.pt");
  ExpectOneLineNamingFile(LoadError(path), path, "gave actions of shape [1, 3], expected [1, 2]");
}

// The file's step, through Policy, against the model it was exported from.
TEST(Policy, StepsARecurrentPolicyLikeItsModel) {
  const TemporaryFolder folder;
  ActorCriticOptions options;
  options.recurrent_size = 4;
  options.hidden_sizes = {16, 8};
  ActorCritic model(options);
  torch::NoGradGuard no_grad;
  model->action_net()->weight.normal_(0.0, 3.0);  // some means beyond [-1, 1]
  ExportPolicy(*model, 1, ObservationSettings{}, folder / "policy.pt");
  Policy policy(folder / "policy.pt", "recurrent");
  ASSERT_TRUE(policy.recurrent());
  EXPECT_EQ(policy.recurrent_size(), 4);
  torch::Tensor states = policy.InitialStates(3);
  torch::Tensor expected_states = torch::zeros({3, 4});
  EXPECT_TRUE(torch::equal(states, expected_states));
  for (int k = 0; k < 3; ++k) {
    const torch::Tensor observations = torch::rand({3, 186});
    const auto [mean, value, next_states] = model->forward_recurrent(observations, expected_states);
    const torch::Tensor actions = policy.Step(observations, states);
    EXPECT_TRUE(torch::allclose(actions, mean.clamp(-1.0, 1.0), 1e-5, 1e-6)) << "step " << k;
    EXPECT_TRUE(torch::allclose(states, next_states, 1e-5, 1e-6)) << "step " << k;
    expected_states = next_states;
  }
  EXPECT_THROW(policy.Act(torch::zeros({3, 186})), c10::Error);  // a zero state every time
}

TEST(Policy, RecurrentFileWithoutStepOrWithWrongStateSize) {
  const TemporaryFolder folder;
  const auto wrong = tp::SavePolicy(tp::WrongStateSizePolicy(), folder / "wrong.pt");
  ExpectOneLineNamingFile(LoadError(wrong), wrong,
                          "step(obs [1, 186], state) gave next states of shape [1, 4], expected "
                          "[1, 3]");
  const auto stepless = tp::SavePolicy(tp::RecurrentModule(R"(
def forward(self, obs: Tensor) -> Tensor:
    return obs[:, 0:2]
)",
                                                           3),
                                       folder / "stepless.pt");
  ExpectOneLineNamingFile(LoadError(stepless), stepless,
                          "recurrent policy (recurrent_size 3) has no initial_state method");
}

TEST(Policy, DefaultNames) {
  EXPECT_EQ(DefaultPolicyName("runs/paper/ppo/shallow_locked/policy.pt"), "shallow_locked");
  EXPECT_EQ(DefaultPolicyName("agents/deep.pt"), "deep");
  EXPECT_EQ(DefaultPolicyName("policy.pt"), "policy");
}

}  // namespace
}  // namespace colav

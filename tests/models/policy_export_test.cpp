#include "models/policy_export.h"

#include <ATen/CPUGeneratorImpl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <utility>

#include "env/environment_spec.h"
#include "models/observation_settings_record.h"
#include "models/torchscript_export.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

constexpr std::int64_t kGlobalStep = 1234;

// Exports `model` to `path` (training step kGlobalStep, the default observation settings) and
// loads the file back.
torch::jit::Module ExportAndLoad(ActorCritic& model, const std::filesystem::path& path) {
  ExportPolicy(*model, kGlobalStep, ObservationSettings{}, path);
  return torch::jit::load(path.string());
}

void ExpectExportMatches(ActorCritic& model, const std::filesystem::path& path) {
  torch::jit::Module loaded = ExportAndLoad(model, path);
  torch::NoGradGuard no_grad;
  torch::Tensor obs = torch::rand({6, model->features_extractor()->observation_size()});
  obs.narrow(1, 0, kNavigationSize).mul_(200.0).sub_(100.0);  // big means: clipping matters
  const auto [mean, value] = model->forward(obs);
  const torch::Tensor action = loaded.forward({obs}).toTensor();
  const torch::Tensor deterministic =
      model->options().squash_actions ? torch::tanh(mean) : mean.clamp(-1.0, 1.0);
  EXPECT_TRUE(torch::allclose(action, deterministic, 1e-5, 1e-6));
  EXPECT_LE(action.abs().max().item<float>(), 1.0f);
  EXPECT_TRUE(torch::allclose(loaded.get_method("value")({obs}).toTensor(), value, 1e-5, 1e-5));
  EXPECT_TRUE(torch::allclose(loaded.get_method("features")({obs}).toTensor(),
                              model->features_extractor()->forward(obs), 1e-5, 1e-6));
  EXPECT_EQ(loaded.attr("global_step").toInt(), kGlobalStep);
  EXPECT_EQ(loaded.attr("extractor").toStringRef(),
            ExtractorKindName(model->options().extractor.kind));
  EXPECT_EQ(loaded.attr("scans").toInt(), model->options().extractor.scans);
  EXPECT_FALSE(loaded.hasattr("recurrent_size"));  // memoryless files stay as they were
}

TEST(PolicyExportTest, BaselinePolicyEqualsTheInProcessPolicy) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  options.log_std_init = -0.5;
  ActorCritic model(options);
  // Large action-head weights, so that some means fall outside [-1, 1].
  torch::NoGradGuard no_grad;
  model->action_net()->weight.normal_(0.0, 3.0);
  ExpectExportMatches(model, directory.path() / "policy.pt");
}

TEST(PolicyExportTest, APrivilegedCriticsPolicyActsAloneAndHasNoValue) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  options.critic_vessels = 3;
  ActorCritic model(options);
  torch::NoGradGuard no_grad;
  model->action_net()->weight.normal_(0.0, 3.0);
  const std::filesystem::path path = directory.path() / "policy.pt";
  torch::jit::Module loaded = ExportAndLoad(model, path);
  const torch::Tensor obs = torch::rand({4, model->features_extractor()->observation_size()});
  const torch::Tensor critic_obs = torch::randn({4, model->options().critic_observation_size()});
  const torch::Tensor mean = model->forward(obs, critic_obs).first;
  EXPECT_TRUE(torch::allclose(loaded.forward({obs}).toTensor(), mean.clamp(-1.0, 1.0), 1e-5, 1e-6));
  EXPECT_FALSE(loaded.find_method("value").has_value());
  EXPECT_TRUE(loaded.find_method("features").has_value());
}

TEST(PolicyExportTest, ASquashingPolicyActsWithTheTanhOfItsMean) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  options.squash_actions = true;
  ActorCritic model(options);
  torch::NoGradGuard no_grad;
  model->action_net()->weight.normal_(0.0, 3.0);
  ExpectExportMatches(model, directory.path() / "policy.pt");
}

// A model whose action mean is `mean` for every observation, with the std `std`.
ActorCritic ConstantMeanModel(ActorCriticOptions options, std::array<float, 2> mean,
                              std::array<float, 2> std) {
  ActorCritic model(std::move(options));
  torch::NoGradGuard no_grad;
  model->action_net()->weight.zero_();
  model->action_net()->bias.copy_(torch::tensor({mean[0], mean[1]}));
  model->log_std().copy_(torch::tensor({std[0], std[1]}).log());
  return model;
}

torch::Tensor ExportedAction(ActorCritic& model, const std::filesystem::path& path) {
  ExportPolicy(*model, 1, ObservationSettings{}, path);
  const torch::Tensor obs = torch::rand({3, model->features_extractor()->observation_size()});
  return torch::jit::load(path.string()).forward({obs}).toTensor();
}

// E[clip(u, -1, 1)], u ~ N(m, s^2), by hand (Phi and phi of a = (-1 - m) / s, b = (1 - m) / s):
// m = 0.5, s = 1: -Phi(-1.5) + 1 - Phi(0.5) + 0.5 (Phi(0.5) - Phi(-1.5)) + phi(-1.5) - phi(0.5)
// = -0.0668072 + 0.3085375 + 0.3123276 + 0.1295176 - 0.3520653 = 0.3315102; m = -3, s = 1:
// -0.9915164; m = 0.2, s = 0.5: 0.1897392. A scale of 0 keeps the clipped mean.
TEST(PolicyExportTest, AScaledStdActsWithTheMeanOfTheClippedGaussian) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  options.deterministic_std_scale = {1.0, 1.0};
  ActorCritic both = ConstantMeanModel(options, {0.5f, -3.0f}, {1.0f, 1.0f});
  const torch::Tensor action = ExportedAction(both, directory.path() / "both.pt");
  EXPECT_NEAR(action[0][0].item<float>(), 0.3315102f, 1e-6);
  EXPECT_NEAR(action[0][1].item<float>(), -0.9915164f, 1e-6);
  EXPECT_TRUE(torch::equal(action[0], action[2]));

  options.deterministic_std_scale = {0.25, 0.0};  // 0.25 * 2 = 0.5 on the thrust only
  ActorCritic thrust = ConstantMeanModel(options, {0.2f, 1.7f}, {2.0f, 3.0f});
  const torch::Tensor thrust_action = ExportedAction(thrust, directory.path() / "thrust.pt");
  EXPECT_NEAR(thrust_action[0][0].item<float>(), 0.1897392f, 1e-6);
  EXPECT_EQ(thrust_action[0][1].item<float>(), 1.0f);
}

// The same against the clipped Gaussian sampled: a policy of std far past the box (as the best
// recipe's, 60-120), at a quarter of its std, on the means of a random network.
TEST(PolicyExportTest, TheExpectedClippedActionIsTheMeanOfSampledClippedActions) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  options.deterministic_std_scale = {0.25, 0.25};
  options.log_std_init = std::log(60.0);
  ActorCritic model(options);
  torch::NoGradGuard no_grad;
  at::Generator generator = at::make_generator<at::CPUGeneratorImpl>(11);
  model->action_net()->weight.normal_(0.0, 20.0, generator);  // means across the noise's width
  const std::filesystem::path path = directory.path() / "policy.pt";
  ExportPolicy(*model, 1, ObservationSettings{}, path);
  const torch::Tensor obs =
      torch::rand({4, model->features_extractor()->observation_size()}, generator);
  const torch::Tensor action = torch::jit::load(path.string()).forward({obs}).toTensor();
  const torch::Tensor mean = model->forward(obs).first;
  const torch::Tensor noise = torch::randn({200000, 4, 2}, generator) * 15.0;
  const torch::Tensor sampled = (mean.unsqueeze(0) + noise).clamp(-1.0, 1.0).mean(0);
  // 200,000 samples of a variable within [-1, 1]: standard error below 0.0023.
  EXPECT_TRUE(torch::allclose(action, sampled, 0.0, 0.01)) << action << sampled;
  EXPECT_GT((mean.abs() > 1.0).sum().item<int>(), 0);  // some means outside the box
}

// A recurrent policy's step acts alike.
TEST(PolicyExportTest, ARecurrentPolicyStepsWithTheExpectedClippedAction) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  options.recurrent_size = 4;
  options.hidden_sizes = {16, 8};
  options.deterministic_std_scale = {1.0, 0.0};
  ActorCritic model = ConstantMeanModel(options, {0.5f, -3.0f}, {1.0f, 1.0f});
  const std::filesystem::path path = directory.path() / "policy.pt";
  torch::jit::Module loaded = ExportAndLoad(model, path);
  const torch::Tensor state = loaded.get_method("initial_state")({2}).toTensor();
  const torch::Tensor obs = torch::rand({2, kObservationSize});
  const torch::Tensor action =
      loaded.get_method("step")({obs, state}).toTuple()->elements()[0].toTensor();
  EXPECT_NEAR(action[1][0].item<float>(), 0.3315102f, 1e-6);
  EXPECT_EQ(action[1][1].item<float>(), -1.0f);
}

// The message of the exception the TorchScript interpreter throws in `action`, or a marker.
template <typename Action>
std::string InterpreterError(Action action) {
  try {
    action();
  } catch (const std::exception& error) {
    return error.what();
  }
  return "<no exception thrown>";
}

// Three steps of the file from its initial_state against forward_recurrent from zeros: a wrong
// gate order, bias or state hand-over shows as a difference by the second step at the latest.
TEST(PolicyExportTest, ARecurrentPolicyStepsLikeTheInProcessModel) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  options.recurrent_size = 4;
  options.hidden_sizes = {16, 8};
  ActorCritic model(options);
  torch::NoGradGuard no_grad;
  model->action_net()->weight.normal_(0.0, 3.0);
  model->recurrent()->bias_ih.normal_(0.0, 0.5);  // zero biases would hide a misplaced one
  model->recurrent()->bias_hh.normal_(0.0, 0.5);
  const std::filesystem::path path = directory.path() / "policy.pt";
  torch::jit::Module loaded = ExportAndLoad(model, path);
  EXPECT_EQ(loaded.attr("recurrent_size").toInt(), 4);
  const std::int64_t batch = 5;
  torch::Tensor state = loaded.get_method("initial_state")({batch}).toTensor();
  EXPECT_TRUE(torch::equal(state, torch::zeros({batch, 4})));
  torch::Tensor expected_state = torch::zeros({batch, 4});
  for (int k = 0; k < 3; ++k) {
    const torch::Tensor obs = torch::rand({batch, kObservationSize});
    const auto [mean, value, next_state] = model->forward_recurrent(obs, expected_state);
    const auto stepped = loaded.get_method("step")({obs, state}).toTuple()->elements();
    const auto valued = loaded.get_method("step_value")({obs, state}).toTuple()->elements();
    EXPECT_TRUE(torch::allclose(stepped[0].toTensor(), mean.clamp(-1.0, 1.0), 1e-5, 1e-6))
        << "step " << k;
    EXPECT_TRUE(torch::allclose(stepped[1].toTensor(), next_state, 1e-5, 1e-6)) << "step " << k;
    EXPECT_TRUE(torch::allclose(valued[0].toTensor(), value, 1e-5, 1e-5)) << "step " << k;
    EXPECT_TRUE(torch::equal(valued[1].toTensor(), stepped[1].toTensor())) << "step " << k;
    state = stepped[1].toTensor();
    expected_state = next_state;
  }
  const torch::Tensor obs = torch::rand({batch, kObservationSize});
  EXPECT_THAT(InterpreterError([&] { loaded.forward({obs}); }),
              testing::HasSubstr("AssertionError: recurrent policy: call step(obs, state) "
                                 "starting from initial_state(B)"));
  EXPECT_THAT(InterpreterError([&] {
                loaded.get_method("step")({obs, torch::zeros({batch, 3})});
              }),
              testing::HasSubstr("states [B, 4] expected"));
}

// A memory beside a privileged critic: step acts as forward_recurrent does, from the observation
// and state alone; there is no step_value, whose critic would need the vessels' rows.
TEST(PolicyExportTest, ARecurrentPrivilegedCriticsPolicyStepsAloneAndHasNoStepValue) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  options.recurrent_size = 4;
  options.critic_vessels = 2;
  options.hidden_sizes = {16, 8};
  ActorCritic model(options);
  torch::NoGradGuard no_grad;
  model->action_net()->weight.normal_(0.0, 3.0);
  const std::filesystem::path path = directory.path() / "policy.pt";
  torch::jit::Module loaded = ExportAndLoad(model, path);
  const std::int64_t batch = 3;
  torch::Tensor state = loaded.get_method("initial_state")({batch}).toTensor();
  torch::Tensor expected_state = torch::zeros({batch, 4});
  for (int k = 0; k < 2; ++k) {
    const torch::Tensor obs = torch::rand({batch, kObservationSize});
    const torch::Tensor critic_obs = torch::randn({batch, options.critic_observation_size()});
    const auto [mean, value, next_state] =
        model->forward_recurrent(obs, expected_state, critic_obs);
    const auto stepped = loaded.get_method("step")({obs, state}).toTuple()->elements();
    EXPECT_TRUE(torch::allclose(stepped[0].toTensor(), mean.clamp(-1.0, 1.0), 1e-5, 1e-6))
        << "step " << k;
    EXPECT_TRUE(torch::allclose(stepped[1].toTensor(), next_state, 1e-5, 1e-6)) << "step " << k;
    state = stepped[1].toTensor();
    expected_state = next_state;
  }
  EXPECT_FALSE(loaded.find_method("step_value").has_value());
  EXPECT_FALSE(loaded.find_method("value").has_value());
}

// With a memory of its own, the critic's state travels apart: step keeps the actor's half of
// forward_recurrent's state, step_value the critic's, each from its own initial_state.
TEST(PolicyExportTest, ASeparateCriticMemoryStepsInStepValue) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  options.recurrent_size = 4;
  options.separate_critic_memory = true;
  options.hidden_sizes = {16, 8};
  ActorCritic model(options);
  torch::NoGradGuard no_grad;
  model->critic_recurrent()->bias_ih.normal_(0.0, 0.5);  // the two cells must not agree
  const std::filesystem::path path = directory.path() / "policy.pt";
  torch::jit::Module loaded = ExportAndLoad(model, path);
  EXPECT_EQ(loaded.attr("recurrent_size").toInt(), 4);
  const std::int64_t batch = 3;
  torch::Tensor actor_state = loaded.get_method("initial_state")({batch}).toTensor();
  torch::Tensor critic_state = actor_state.clone();
  torch::Tensor expected_state = torch::zeros({batch, 8});
  for (int k = 0; k < 3; ++k) {
    const torch::Tensor obs = torch::rand({batch, kObservationSize});
    const auto [mean, value, next_state] = model->forward_recurrent(obs, expected_state);
    const auto stepped = loaded.get_method("step")({obs, actor_state}).toTuple()->elements();
    const auto valued = loaded.get_method("step_value")({obs, critic_state}).toTuple()->elements();
    EXPECT_TRUE(torch::allclose(stepped[0].toTensor(), mean.clamp(-1.0, 1.0), 1e-5, 1e-6))
        << "step " << k;
    EXPECT_TRUE(torch::allclose(stepped[1].toTensor(), next_state.narrow(1, 0, 4), 1e-5, 1e-6))
        << "step " << k;
    EXPECT_TRUE(torch::allclose(valued[0].toTensor(), value, 1e-5, 1e-5)) << "step " << k;
    EXPECT_TRUE(torch::allclose(valued[1].toTensor(), next_state.narrow(1, 4, 4), 1e-5, 1e-6))
        << "step " << k;
    actor_state = stepped[1].toTensor();
    critic_state = valued[1].toTensor();
    expected_state = next_state;
  }
}

// Makes `options` a VAE extractor of `architecture` with an untrained encoder saved in `folder`.
void UseSavedEncoder(ActorCriticOptions& options, VaeArchitecture architecture,
                     const std::filesystem::path& folder) {
  options.extractor.kind =
      architecture == VaeArchitecture::kDeep ? ExtractorKind::kVaeDeep : ExtractorKind::kVaeShallow;
  options.extractor.encoder = folder / "encoder.pt";
  ExportEncoder(VaeEncoder(VaeEncoderOptions{architecture, 12}), ObservationSettings{},
                options.extractor.encoder);
}

TEST(PolicyExportTest, DeepVaePolicyEqualsTheInProcessPolicy) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  UseSavedEncoder(options, VaeArchitecture::kDeep, directory.path());
  ActorCritic model(options);
  ExpectExportMatches(model, directory.path() / "policy.pt");
  torch::jit::Module loaded = torch::jit::load((directory.path() / "policy.pt").string());
  EXPECT_TRUE(loaded.attr("locked").toBool());
  options.extractor.head = EncoderHead::kReference;  // the ReLU after the head is exported too
  ActorCritic reference(options);
  ExpectExportMatches(reference, directory.path() / "reference.pt");
}

TEST(PolicyExportTest, PoliciesOfThreeScansEqualTheInProcessPolicy) {
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options;
  options.extractor.scans = 3;
  ActorCritic baseline(options);
  ExpectExportMatches(baseline, directory.path() / "baseline.pt");
  UseSavedEncoder(options, VaeArchitecture::kShallow, directory.path());
  options.extractor.head = EncoderHead::kReference;
  ActorCritic vae(options);
  ExpectExportMatches(vae, directory.path() / "vae.pt");
}

// Either way round: a policy of 3 scans given one scan, and one of 1 scan given three (which it
// could otherwise read the first of, silently).
// A model trained on normalised navigation values, exported with their normalisation, is a policy
// of raw observations: the same outputs, to the bit, as the model given the normalised values.
TEST(PolicyExportTest, APolicyWithNavigationNormalisationTakesRawObservations) {
  testing_util::TemporaryFolder directory;
  ActorCritic model(ActorCriticOptions{});
  NavigationNormalization navigation;
  navigation.mean = {0.5f, -0.01f, 0.002f, 0.1f, -0.3f, 2.0f};
  navigation.spread = {0.05f, 0.06f, 0.04f, 0.25f, 0.7f, 1.5f};
  const std::filesystem::path path = directory.path() / "policy.pt";
  ExportPolicy(*model, 7, ObservationSettings{}, path, navigation);
  torch::jit::Module loaded = torch::jit::load(path.string());
  torch::NoGradGuard no_grad;
  const torch::Tensor raw = torch::rand({5, kObservationSize});
  torch::Tensor normalised = raw.clone();
  for (std::int64_t row = 0; row < raw.size(0); ++row) {
    for (int j = 0; j < kNavigationSize; ++j) {  // by hand, in float
      normalised[row][j] = (raw[row][j].item<float>() - navigation.mean[j]) / navigation.spread[j];
    }
  }
  const auto [mean, value] = model->forward(normalised);
  EXPECT_TRUE(torch::equal(loaded.get_method("features")({raw}).toTensor(),
                           model->features_extractor()->forward(normalised)));
  EXPECT_TRUE(torch::allclose(loaded.forward({raw}).toTensor(), mean.clamp(-1.0, 1.0), 1e-6, 1e-7));
  EXPECT_TRUE(torch::allclose(loaded.get_method("value")({raw}).toTensor(), value, 1e-6, 1e-6));
  EXPECT_TRUE(torch::equal(
      loaded.attr("navigation_spread").toTensor(),
      torch::tensor(std::vector<float>(navigation.spread.begin(), navigation.spread.end()))));
  // Without a normalisation the raw values go through, as before.
  ExportPolicy(*model, 7, ObservationSettings{}, directory.path() / "plain.pt");
  torch::jit::Module plain = torch::jit::load((directory.path() / "plain.pt").string());
  EXPECT_FALSE(plain.hasattr("navigation_mean"));
  EXPECT_TRUE(torch::equal(plain.get_method("features")({raw}).toTensor().narrow(1, 0, 6),
                           raw.narrow(1, 0, 6)));
}

TEST(PolicyExportTest, APolicyRejectsObservationsOfAnotherWidth) {
  testing_util::TemporaryFolder directory;
  for (const auto& [scans, given_scans] : {std::pair{3, 1}, std::pair{1, 3}}) {
    ActorCriticOptions options;
    options.extractor.scans = scans;
    ActorCritic model(options);
    const std::filesystem::path path = directory.path() / "policy.pt";
    torch::jit::Module loaded = ExportAndLoad(model, path);
    const std::string expected_width = std::to_string(kNavigationSize + scans * kNumRays);
    const torch::Tensor obs = torch::rand({2, kNavigationSize + given_scans * kNumRays});
    for (const std::string method : {"forward", "value", "features"}) {
      try {
        loaded.get_method(method)({obs});
        ADD_FAILURE() << method << " accepted " << given_scans << " scan(s)";
      } catch (const std::exception& error) {  // the interpreter's runtime_error
        EXPECT_THAT(error.what(), testing::HasSubstr("observations [B, " + expected_width + "]"));
      }
    }
  }
}

TEST(PolicyExportTest, RecordsTheObservationSettingsAndTheirLayout) {
  testing_util::TemporaryFolder directory;
  ActorCritic model{ActorCriticOptions{}};
  for (const ClosenessTransform closeness :
       {ClosenessTransform::kLinear, ClosenessTransform::kLog}) {
    const std::filesystem::path path = directory.path() / "policy.pt";
    ExportPolicy(*model, 1, ObservationSettings{closeness}, path);
    torch::jit::Module loaded = torch::jit::load(path.string());
    EXPECT_EQ(RecordedObservationSettings(loaded, path.string()), ObservationSettings{closeness});
    const std::string layout = loaded.attr("observation_layout").toStringRef();
    const bool log = closeness == ClosenessTransform::kLog;
    EXPECT_EQ(layout.find("1 - ln(1+d)/ln(151)") != std::string::npos, log) << layout;
    EXPECT_EQ(layout.find("1 - d/150") != std::string::npos, !log) << layout;
  }
}

TEST(PolicyExportTest, AFileWithoutRecordedSettingsHasNone) {
  testing_util::TemporaryFolder directory;
  torch::jit::Module bare("Bare");
  EXPECT_FALSE(RecordedObservationSettings(bare, "bare.pt").has_value());
  bare.register_attribute(kObservationSettingsAttribute, c10::StringType::get(),
                          std::string("env:\n  closeness: cubic\n"));
  EXPECT_THAT(testing_util::UserErrorMessage([&] { RecordedObservationSettings(bare, "bare.pt"); }),
              ::testing::HasSubstr("bare.pt: key 'env.closeness' = 'cubic'"));
}

}  // namespace
}  // namespace colav

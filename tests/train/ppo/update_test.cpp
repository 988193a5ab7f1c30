#include "train/ppo/update.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "models/torchscript_export.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

PpoOptions SmallOptions() {
  PpoOptions options;
  options.n_envs = 4;
  options.n_steps = 8;
  options.batch_size = 8;
  options.n_epochs = 2;
  options.adam.learning_rate = 1e-2;  // large steps, so that trained weights visibly move
  return options;
}

// A rollout of random observations, actions and rewards.
RolloutBuffer SyntheticRollout(const PpoOptions& options) {
  RolloutBuffer buffer(options.n_steps, options.n_envs, kObservationSize);
  const int N = options.n_envs;
  for (int t = 0; t < options.n_steps; ++t) {
    const torch::Tensor obs = torch::rand({N, kObservationSize});
    std::copy_n(obs.data_ptr<float>(), N * kObservationSize, buffer.observations(t));
    const torch::Tensor actions = torch::randn({N, kActionSize});
    std::copy_n(actions.data_ptr<float>(), N * kActionSize, buffer.actions(t));
    for (int e = 0; e < N; ++e) {
      buffer.log_probs(t)[e] = -2.0f;
      buffer.values(t)[e] = 0.0f;
      buffer.rewards(t)[e] = torch::randn({}).item<float>();
      buffer.dones(t)[e] = 0;
      buffer.bootstrapped(t)[e] = 0;
      buffer.final_values(t)[e] = 0.0f;
    }
  }
  for (int e = 0; e < N; ++e) buffer.last_values()[e] = 0.0f;
  buffer.ComputeReturnsAndAdvantages(0.99, 0.95);
  return buffer;
}

std::vector<torch::Tensor> Clones(const std::vector<torch::Tensor>& tensors) {
  std::vector<torch::Tensor> clones;
  for (const auto& tensor : tensors) clones.push_back(tensor.detach().clone());
  return clones;
}

TEST(PpoUpdaterTest, LockedEncoderStaysBitIdenticalWhileAnUnlockedOneChanges) {
  testing_util::TemporaryFolder directory;
  torch::manual_seed(9);
  const std::filesystem::path encoder = directory.path() / "encoder.pt";
  ExportEncoder(VaeEncoder(VaeEncoderOptions{VaeArchitecture::kShallow, 12}), ObservationSettings{},
                encoder);
  const PpoOptions options = SmallOptions();
  const RolloutBuffer buffer = SyntheticRollout(options);
  for (const bool locked : {true, false}) {
    ActorCriticOptions model_options;
    model_options.extractor.kind = ExtractorKind::kVaeShallow;
    model_options.extractor.encoder = encoder;
    model_options.extractor.locked = locked;
    ActorCritic model(model_options);
    const auto encoder_before = Clones(model->features_extractor()->parameters());
    const auto head_before = model->action_net()->weight.detach().clone();
    PpoUpdater updater(model, options);
    auto generator = at::make_generator<at::CPUGeneratorImpl>(1);
    const UpdateStats stats = updater.Update(buffer, generator);
    EXPECT_EQ(stats.n_updates, options.n_epochs);
    EXPECT_TRUE(std::isfinite(stats.loss));
    EXPECT_EQ(updater.optimizer().step_count(), options.n_epochs * 32 / options.batch_size);
    const auto encoder_after = model->features_extractor()->parameters();
    for (std::size_t i = 0; i < encoder_after.size(); ++i) {
      EXPECT_EQ(torch::equal(encoder_after[i], encoder_before[i]), locked)
          << (locked ? "locked" : "unlocked") << " parameter " << i;
    }
    EXPECT_FALSE(torch::equal(model->action_net()->weight, head_before));
  }
}

TEST(PpoUpdaterTest, NonFiniteLossStopsTraining) {
  const PpoOptions options = SmallOptions();
  RolloutBuffer buffer = SyntheticRollout(options);
  buffer.rewards(3)[1] = std::numeric_limits<float>::quiet_NaN();
  buffer.ComputeReturnsAndAdvantages(0.99, 0.95);
  PpoUpdater updater(ActorCritic(ActorCriticOptions{}), options);
  auto generator = at::make_generator<at::CPUGeneratorImpl>(1);
  EXPECT_THROW(updater.Update(buffer, generator), TrainingDiverged);
}

// A held actor (the critic's warm-up): one update over one minibatch moves the critic's own
// parameters exactly as an update of everything does (Adam's step is elementwise and no clipping
// binds), and leaves every other parameter, the unlocked extractor's and the log std included,
// bit for bit. A restart gives a fresh Adam.
TEST(PpoUpdaterTest, AHeldActorLeavesAllButTheCriticsOwnParametersBitIdentical) {
  PpoOptions options = SmallOptions();
  options.n_epochs = 1;
  options.batch_size = options.n_envs * options.n_steps;  // one minibatch
  options.max_grad_norm = 1e6;
  torch::manual_seed(5);
  const RolloutBuffer buffer = SyntheticRollout(options);
  ActorCriticOptions model_options;
  model_options.extractor.kind = ExtractorKind::kBaseline;  // trains with the actor
  ActorCritic held(model_options);
  ActorCritic whole(model_options);
  const auto before = Clones(held->parameters());

  PpoUpdater held_updater(held, options);
  held_updater.set_actor_held(true);
  auto generator = at::make_generator<at::CPUGeneratorImpl>(1);
  held_updater.Update(buffer, generator);
  PpoUpdater whole_updater(whole, options);
  generator = at::make_generator<at::CPUGeneratorImpl>(1);
  whole_updater.Update(buffer, generator);

  const std::vector<torch::Tensor> critic = held->CriticParameters();
  const auto held_after = held->named_parameters();
  const auto whole_after = whole->named_parameters();
  int critic_count = 0;
  for (std::size_t i = 0; i < held_after.size(); ++i) {
    const std::string& name = held_after[i].key();
    const torch::Tensor& parameter = held_after[i].value();
    const bool critics = std::any_of(critic.begin(), critic.end(),
                                     [&](const torch::Tensor& c) { return c.is_same(parameter); });
    critic_count += critics;
    if (critics) {
      EXPECT_FALSE(torch::equal(parameter, before[i])) << name;
      EXPECT_TRUE(torch::equal(parameter, whole_after[name])) << name;
    } else {
      EXPECT_TRUE(torch::equal(parameter, before[i])) << name;
      EXPECT_FALSE(torch::equal(whole_after[name], before[i])) << name;
    }
  }
  EXPECT_EQ(critic_count, 8);  // three trunk layers and the head, weights and biases

  ASSERT_EQ(held_updater.optimizer().step_count(), 1);
  held_updater.RestartOptimizer();
  EXPECT_EQ(held_updater.optimizer().step_count(), 0);
  for (const torch::Tensor& moment : held_updater.optimizer().exp_avg_sq()) {
    EXPECT_EQ(moment.abs().max().item<float>(), 0.0f);
  }
}

// ppo.std_max: a log std that starts above log(std_max) is clamped when the updater starts, and a
// strong entropy bonus, which widens the std at every step, pushes it no further than log(std_max);
// unbounded (0, the default) the same update widens it past its start. A bound above the start
// leaves it alone.
TEST(PpoUpdaterTest, StdMaxBoundsTheStdAtTheStartAndAfterEveryStep) {
  PpoOptions options = SmallOptions();
  options.loss.ent_coef = 1.0;  // d loss / d log std = sum - 1 per minibatch: widening
  torch::manual_seed(3);
  const RolloutBuffer buffer = SyntheticRollout(options);
  ActorCriticOptions model_options;
  model_options.log_std_init = 1.0;  // std e = 2.72

  const auto log_std_after = [&](double std_max, bool update) {
    options.std_max = std_max;
    ActorCritic model(model_options);
    PpoUpdater updater(model, options);
    if (update) {
      auto generator = at::make_generator<at::CPUGeneratorImpl>(1);
      updater.Update(buffer, generator);
    }
    return std::vector<float>(model->log_std().data_ptr<float>(),
                              model->log_std().data_ptr<float>() + kActionSize);
  };
  const float log_two = std::log(2.0f);
  for (const float log_std : log_std_after(2.0, false)) EXPECT_EQ(log_std, log_two);
  for (const float log_std : log_std_after(2.0, true)) EXPECT_EQ(log_std, log_two);
  for (const float log_std : log_std_after(10.0, false)) EXPECT_EQ(log_std, 1.0f);
  for (const float log_std : log_std_after(0.0, true)) EXPECT_GT(log_std, 1.0f);
}

}  // namespace
}  // namespace colav

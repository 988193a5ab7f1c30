#include "train/ppo/update.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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

}  // namespace
}  // namespace colav

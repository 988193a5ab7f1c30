#include "train/ppo/checkpoint.h"

#include <gtest/gtest.h>

#include <fstream>

#include "src/error.h"
#include "tests/src/test_util.h"
#include "train/ppo/config.h"
#include "train/ppo/trainer.h"
#include "train/ppo/update.h"

namespace colav {
namespace {

TEST(PpoCheckpointTest, RoundTripRestoresWeightsOptimiserGeneratorAndCounters) {
  testing_util::TemporaryFolder directory;
  PpoOptions options;
  options.n_envs = 2;
  options.n_steps = 8;
  options.batch_size = 4;
  ActorCriticOptions model_options;
  model_options.seed = 1;
  ActorCritic model(model_options);
  PpoUpdater updater(model, options);
  // Some Adam steps, so that the optimiser state is not trivial.
  for (int step = 0; step < 3; ++step) {
    std::vector<torch::Tensor> gradients;
    for (const auto& p : model->TrainableParameters()) gradients.push_back(torch::randn_like(p));
    updater.optimizer().Step(gradients);
  }
  auto generator = at::make_generator<at::CPUGeneratorImpl>(5);
  torch::randn({10}, generator);
  const TrainingCounters counters{30000, 12, 3, 17, 42.5};
  SaveCheckpoint(directory.path(), *model, updater.optimizer(), generator, counters,
                 ObservationSettings{}, true);
  EXPECT_TRUE(std::filesystem::exists(directory.path() / "policy.pt"));
  EXPECT_TRUE(std::filesystem::exists(directory.path() / "checkpoints" / "policy_30000.pt"));

  model_options.seed = 2;
  ActorCritic restored(model_options);
  PpoUpdater restored_updater(restored, options);
  auto restored_generator = at::make_generator<at::CPUGeneratorImpl>(6);
  const TrainingCounters loaded =
      LoadCheckpoint(directory.path(), *restored, restored_updater.optimizer(), restored_generator);
  EXPECT_EQ(loaded.global_step, 30000);
  EXPECT_EQ(loaded.n_updates, 12);
  EXPECT_EQ(loaded.rollouts, 3);
  EXPECT_EQ(loaded.episodes, 17);
  EXPECT_DOUBLE_EQ(loaded.wall_s, 42.5);
  const auto original = model->parameters(), copy = restored->parameters();
  for (std::size_t i = 0; i < original.size(); ++i) EXPECT_TRUE(torch::equal(original[i], copy[i]));
  EXPECT_EQ(restored_updater.optimizer().step_count(), 3);
  for (std::size_t i = 0; i < updater.optimizer().exp_avg().size(); ++i) {
    EXPECT_TRUE(
        torch::equal(updater.optimizer().exp_avg()[i], restored_updater.optimizer().exp_avg()[i]));
    EXPECT_TRUE(torch::equal(updater.optimizer().exp_avg_sq()[i],
                             restored_updater.optimizer().exp_avg_sq()[i]));
  }
  EXPECT_TRUE(torch::equal(torch::randn({4}, generator), torch::randn({4}, restored_generator)));
}

TEST(PpoCheckpointTest, MissingStateIsAUserError) {
  testing_util::TemporaryFolder directory;
  ActorCritic model(ActorCriticOptions{});
  Adam optimizer(model->TrainableParameters(), AdamOptions{});
  auto generator = at::make_generator<at::CPUGeneratorImpl>(5);
  EXPECT_THROW(LoadCheckpoint(directory.path(), *model, optimizer, generator), UserError);
}

Config TinyRun(std::int64_t total_steps) {
  Config config = Config::Defaults(PpoRunBinding().Schema());
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"ppo.total_steps", std::to_string(total_steps)},
           {"ppo.n_envs", "2"},
           {"ppo.n_steps", "16"},
           {"ppo.batch_size", "8"},
           {"ppo.n_epochs", "1"},
           {"train.checkpoint_interval", "32"},
           {"train.env_threads", "1"}}) {
    config.Set(key, value, "test");
  }
  return config;
}

PpoRunSummary Train(const Config& config, const std::filesystem::path& run_dir, bool resume) {
  return TrainPpo(PpoRunBinding().Read(config), config.ToJson(), run_dir, resume);
}

std::size_t CountLines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

TEST(PpoCheckpointTest, ResumedRunContinuesFromTheCheckpointStep) {
  testing_util::TemporaryFolder directory;
  const PpoRunSummary first = Train(TinyRun(64), directory.path(), /*resume=*/false);
  EXPECT_TRUE(first.finished);
  EXPECT_EQ(first.counters.global_step, 64);
  EXPECT_EQ(first.counters.rollouts, 2);
  EXPECT_EQ(first.counters.n_updates, 2);
  for (const char* file : {"policy.pt", "training_state.pt", "summary.json", "episodes.csv",
                           "updates.csv", "checkpoints/policy_32.pt", "checkpoints/policy_64.pt"}) {
    EXPECT_TRUE(std::filesystem::exists(directory.path() / file)) << file;
  }
  EXPECT_EQ(CountLines(directory.path() / "updates.csv"), 3U);

  const PpoRunSummary second = Train(TinyRun(128), directory.path(), /*resume=*/true);
  EXPECT_EQ(second.session_steps, 64);
  EXPECT_EQ(second.counters.global_step, 128);
  EXPECT_EQ(second.counters.n_updates, 4);
  EXPECT_EQ(CountLines(directory.path() / "updates.csv"), 5U);

  ActorCritic model(PpoRunBinding().Read(TinyRun(128)).model);
  Adam optimizer(model->TrainableParameters(), AdamOptions{});
  auto generator = at::make_generator<at::CPUGeneratorImpl>(0);
  LoadCheckpoint(directory.path(), *model, optimizer, generator);
  EXPECT_EQ(optimizer.step_count(), 4 * 32 / 8);  // 4 rollouts of 32 samples, batches of 8
}

}  // namespace
}  // namespace colav

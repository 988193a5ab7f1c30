#include "train/vae/trainer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "models/torchscript_export.h"
#include "src/seeding.h"
#include "src/training_diverged.h"
#include "tests/src/test_util.h"
#include "train/dataset/generation.h"
#include "train/vae/checkpoint.h"
#include "train/vae/data.h"
#include "train/vae/seed_run.h"
#include "train/vae/summary.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;

// A few hundred scans: 30 simulator + 90 synthetic sources, x 3 rows.
std::filesystem::path WriteTinyDataset(const TemporaryFolder& folder) {
  DatasetGenerationOptions options;
  options.sim_scans = 30;
  options.synthetic_scans = 90;
  options.seed = 5;
  const std::filesystem::path path = folder / "tiny.h5";
  WriteScanDataset(GenerateScanDataset(options, [](std::int64_t) {}), path);
  return path;
}

VaeTrainingOptions TinyOptions(const std::filesystem::path& data, std::int64_t epochs) {
  VaeTrainingOptions options;
  options.data_path = data.string();
  options.epochs = epochs;
  options.evaluation_batch_size = 50;  // several evaluation batches
  return options;
}

bool Finite(const EpochLosses& h) {
  return std::isfinite(h.train_bce) && std::isfinite(h.train_kl) &&
         std::isfinite(h.validation_bce) && std::isfinite(h.validation_kl);
}

TEST(VaeTrainerTest, TinyRunWritesEveryOutputAndResumesFinishedSeeds) {
  const TemporaryFolder folder;
  const VaeTrainingOptions options = TinyOptions(WriteTinyDataset(folder), 2);
  const VaeData data = LoadVaeData(options.data_path, options.transform);
  ASSERT_GT(data.train.size(0), 200);

  std::vector<SeedResult> results;
  for (std::int64_t k = 0; k < 2; ++k) {
    results.push_back(RunVaeSeed(data, options, k, folder / ("run/seed_" + std::to_string(k))));
  }
  WriteRunSummary(folder / "run", options, results);
  for (const std::string name :
       {"losses.csv", "encoder.pt", "vae.pt", "checkpoint.pt", "result.json"}) {
    EXPECT_TRUE(std::filesystem::exists(folder / "run/seed_0" / name)) << name;
  }
  EXPECT_TRUE(std::filesystem::exists(folder / "run/summary.md"));
  ASSERT_EQ(results[0].history.size(), 2U);
  for (const SeedResult& r : results) {
    for (const EpochLosses& h : r.history) EXPECT_TRUE(Finite(h));
    EXPECT_TRUE(std::isfinite(r.test_error));
    EXPECT_NEAR(r.test_error, r.test_bce + r.test_kl, 1e-9);
    EXPECT_EQ(r.kl_per_dimension.size(), 12U);
    EXPECT_GE(r.active_dimensions, 0);
    EXPECT_LE(r.active_dimensions, 12);
  }
  EXPECT_NE(results[0].test_error, results[1].test_error);  // independent seeds

  std::ifstream summary_file(folder / "run/summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  EXPECT_EQ(summary["test_error_per_seed"].size(), 2U);
  EXPECT_NEAR(summary["test_error"]["mean"].get<double>(),
              (results[0].test_error + results[1].test_error) / 2.0, 1e-9);
  EXPECT_LE(summary["test_error"]["low"].get<double>(),
            summary["test_error"]["mean"].get<double>());

  // The exported encoder gives the trained encoder's mu.
  VaeEncoder encoder = LoadVaeEncoder(folder / "run/seed_0/encoder.pt");
  ConvVae model = LoadSeedModel(options, 0, folder / "run/seed_0");
  const torch::Tensor x = data.test.narrow(0, 0, 5);
  EXPECT_TRUE(torch::allclose(encoder->Mu(x), model->encoder()->Mu(x), 1e-5, 1e-6));

  // A finished seed is reused as it is.
  const SeedResult again = RunVaeSeed(data, options, 0, folder / "run/seed_0");
  EXPECT_EQ(again.test_error, results[0].test_error);
  EXPECT_EQ(again.seconds, results[0].seconds);
}

TEST(VaeTrainerTest, ResumedRunEqualsUninterruptedRun) {
  const TemporaryFolder folder;
  const VaeTrainingOptions options = TinyOptions(WriteTinyDataset(folder), 3);
  const VaeData data = LoadVaeData(options.data_path, options.transform);
  const SeedResult uninterrupted = RunVaeSeed(data, options, 0, folder / "a");

  // Interrupted after epoch 1: the checkpoint a run would have left.
  VaeTrainer trainer(options, data, VaeRunSeed(options, 0));
  VaeProgress progress;
  progress.history.push_back(trainer.RunEpoch(1));
  SaveVaeCheckpoint(folder / "b/checkpoint.pt", VaeRunSignature(options, 0), trainer.model(),
                    trainer.optimizer(), progress);
  const SeedResult resumed = RunVaeSeed(data, options, 0, folder / "b");
  ASSERT_EQ(resumed.history.size(), 3U);
  for (std::size_t e = 0; e < 3; ++e) {
    EXPECT_DOUBLE_EQ(resumed.history[e].train_bce, uninterrupted.history[e].train_bce);
    EXPECT_DOUBLE_EQ(resumed.history[e].validation_kl, uninterrupted.history[e].validation_kl);
  }
  EXPECT_DOUBLE_EQ(resumed.test_error, uninterrupted.test_error);

  // Other settings refuse the checkpoint.
  VaeTrainingOptions other = options;
  other.beta = 2.0;
  std::filesystem::remove(folder / "b/result.json");
  EXPECT_THROW(RunVaeSeed(data, other, 0, folder / "b"), UserError);
  VaeTrainingOptions clipped = options;
  clipped.clip_noisy_scans = true;
  EXPECT_THROW(RunVaeSeed(data, clipped, 0, folder / "b"), UserError);
}

TEST(VaeTrainerTest, LossDecreasesOverEpochs) {
  const TemporaryFolder folder;
  // A tiny training split gives few steps per epoch: a larger learning rate makes progress visible.
  VaeTrainingOptions options = TinyOptions(WriteTinyDataset(folder), 12);
  options.learning_rate = 5e-3;
  const VaeData data = LoadVaeData(options.data_path, options.transform);
  VaeTrainer trainer(options, data, 17);
  std::vector<EpochLosses> history;
  for (std::int64_t epoch = 1; epoch <= options.epochs; ++epoch) {
    history.push_back(trainer.RunEpoch(epoch));
  }
  const auto total = [](const EpochLosses& h) { return h.train_bce + h.train_kl; };
  const auto validation = [](const EpochLosses& h) { return h.validation_bce + h.validation_kl; };
  EXPECT_LT(total(history.back()), 0.9 * total(history.front()));
  EXPECT_LT(validation(history.back()), validation(history.front()));
}

TEST(VaeTrainerTest, SameSeedSameModel) {
  const TemporaryFolder folder;
  const VaeTrainingOptions options = TinyOptions(WriteTinyDataset(folder), 1);
  const VaeData data = LoadVaeData(options.data_path, options.transform);
  VaeTrainer a(options, data, 3);
  VaeTrainer b(options, data, 3);
  EXPECT_DOUBLE_EQ(a.RunEpoch(1).train_bce, b.RunEpoch(1).train_bce);
}

// A NaN reaching the loss stops the epoch before its results could be saved (the guard of
// train_vae, which then exits with kDivergedStatus and keeps the last checkpoint).
TEST(VaeTrainerTest, NonFiniteLossThrowsTrainingDiverged) {
  const TemporaryFolder folder;
  const VaeTrainingOptions options = TinyOptions(WriteTinyDataset(folder), 1);
  VaeData data = LoadVaeData(options.data_path, options.transform);
  data.train[3][7] = std::numeric_limits<float>::quiet_NaN();  // past LoadVaeData's checks
  VaeTrainer trainer(options, data, 3);
  try {
    trainer.RunEpoch(1);
    FAIL() << "expected TrainingDiverged";
  } catch (const TrainingDiverged& diverged) {
    EXPECT_NE(std::string(diverged.what()).find("in epoch 1"), std::string::npos)
        << diverged.what();
  }
}

}  // namespace
}  // namespace colav

#include "train/vae/seed_run.h"

#include <chrono>
#include <fstream>
#include <sstream>

#include "models/torchscript_export.h"
#include "src/atomic_file.h"
#include "src/cli.h"
#include "src/progress.h"
#include "src/seeding.h"
#include "train/vae/checkpoint.h"
#include "train/vae/evaluation.h"
#include "train/vae/trainer.h"

namespace colav {
namespace {

constexpr char kCheckpointFile[] = "checkpoint.pt";
constexpr char kResultFile[] = "result.json";
// Minibatches between two progress-line updates.
constexpr std::int64_t kProgressInterval = 50;

// The finished result in `seed_dir` made with `signature`, if any.
bool ReadFinishedResult(const std::filesystem::path& seed_dir, const std::string& signature,
                        SeedResult& result) {
  const std::filesystem::path path = seed_dir / kResultFile;
  std::ifstream file(path);
  if (!file) return false;
  const nlohmann::json json = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded() || json.value("signature", "") != signature) return false;
  result = SeedResultFromJson(json, path.string());
  return true;
}

}  // namespace

std::uint64_t VaeRunSeed(const VaeTrainingOptions& options, std::int64_t index) {
  return DeriveSeed(options.seed, "vae.run", static_cast<std::uint64_t>(index));
}

std::string VaeRunSignature(const VaeTrainingOptions& options, std::int64_t index) {
  std::ostringstream signature;
  signature << DescribeVae(options) << "; data " << options.data_path << " ("
            << (options.transform == ClosenessTransform::kLog ? "log" : "linear") << ", noise "
            << options.train_noise_variance << (options.clip_noisy_scans ? ", clipped" : "")
            << "); batch " << options.batch_size << ", lr " << options.learning_rate << ", epochs "
            << options.epochs << "; seed " << options.seed << "/" << index;
  return signature.str();
}

SeedResult RunVaeSeed(const VaeData& data, const VaeTrainingOptions& options, std::int64_t index,
                      const std::filesystem::path& seed_dir) {
  const std::string signature = VaeRunSignature(options, index);
  SeedResult result;
  if (ReadFinishedResult(seed_dir, signature, result)) return result;

  const auto start = std::chrono::steady_clock::now();
  VaeTrainer trainer(options, data, VaeRunSeed(options, index));
  const std::filesystem::path checkpoint = seed_dir / kCheckpointFile;
  VaeProgress progress;
  if (std::filesystem::exists(checkpoint)) {
    progress = LoadVaeCheckpoint(checkpoint, signature, trainer.model(), trainer.optimizer());
  }
  const double seconds_before = progress.seconds;

  const std::int64_t train_size = data.train.size(0);
  ProgressOptions bar_options;
  bar_options.initial_done = static_cast<std::int64_t>(progress.history.size()) * train_size;
  ProgressBar bar("seed " + std::to_string(index), options.epochs * train_size, "scans",
                  bar_options);
  for (auto epoch = static_cast<std::int64_t>(progress.history.size()) + 1; epoch <= options.epochs;
       ++epoch) {
    std::int64_t batches = 0;
    const std::int64_t done_before = (epoch - 1) * train_size;
    progress.history.push_back(trainer.RunEpoch(epoch, [&](std::int64_t done, double loss) {
      if (++batches % kProgressInterval != 0) return;
      bar.Update(done_before + done,
                 {{"epoch", std::to_string(epoch) + "/" + std::to_string(options.epochs)},
                  {"loss", std::to_string(loss)}});
    }));
    progress.seconds = seconds_before + SecondsSince(start);
    const EpochLosses& last = progress.history.back();
    bar.Update(epoch * train_size,
               {{"epoch", std::to_string(epoch) + "/" + std::to_string(options.epochs)},
                {"train", std::to_string(last.train_bce + options.beta * last.train_kl)},
                {"val", std::to_string(last.validation_bce + options.beta * last.validation_kl)}});
    WriteTextFileAtomically(seed_dir / "losses.csv", LossesCsv(progress.history));
    SaveVaeCheckpoint(checkpoint, signature, trainer.model(), trainer.optimizer(), progress);
    if (StopFlag::StopRequested()) {
      throw TrainingStopped("stopped after epoch " + std::to_string(epoch) + "; checkpoint " +
                            checkpoint.string() + " (run the same command to resume)");
    }
  }
  bar.Finish();

  const ObservationSettings scans_settings{options.transform};
  ExportEncoder(trainer.model()->encoder(), scans_settings, seed_dir / "encoder.pt");
  ExportVae(trainer.model(), scans_settings, seed_dir / "vae.pt");
  const VaeEvaluation test =
      EvaluateVae(trainer.model(), data.test, options.beta, DeriveSeed(trainer.seed(), "vae.test"),
                  options.evaluation_batch_size);
  result.index = index;
  result.seed = trainer.seed();
  result.test_error = test.total;
  result.test_bce = test.bce;
  result.test_kl = test.kl;
  result.active_dimensions = test.active_dimensions;
  const torch::Tensor kl = test.kl_per_dimension.contiguous();
  result.kl_per_dimension.assign(kl.data_ptr<double>(), kl.data_ptr<double>() + kl.numel());
  result.seconds = seconds_before + SecondsSince(start);
  result.history = progress.history;
  nlohmann::json json = SeedResultToJson(result);
  json["signature"] = signature;
  WriteTextFileAtomically(seed_dir / kResultFile, json.dump(2) + "\n");
  return result;
}

ConvVae LoadSeedModel(const VaeTrainingOptions& options, std::int64_t index,
                      const std::filesystem::path& seed_dir) {
  ConvVae model(options.model);
  Adam optimizer = MakeVaeOptimizer(model->parameters(), options.learning_rate);
  LoadVaeCheckpoint(seed_dir / kCheckpointFile, VaeRunSignature(options, index), model, optimizer);
  return model;
}

}  // namespace colav

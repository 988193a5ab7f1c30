// train_vae: pre-trains ShallowConvVAE / DeepConvVAE on a generate_dataset file over one or more
// seeds; writes per seed the losses, TorchScript encoder and VAE, a resumable checkpoint and the
// test error, and across seeds the paper's table (summary.json, summary.md) and figures.
#include <spdlog/spdlog.h>
#include <torch/torch.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "src/cli.h"
#include "src/logging.h"
#include "src/run_folder.h"
#include "src/statistics.h"
#include "src/training_diverged.h"
#include "train/vae/config.h"
#include "train/vae/data.h"
#include "train/vae/figures.h"
#include "train/vae/seed_run.h"
#include "train/vae/summary.h"

namespace colav {
namespace {

constexpr std::int64_t kReconstructionScans = 6;

void DrawRunFigures(const VaeData& data, const VaeTrainingOptions& options,
                    const std::vector<SeedResult>& results, const std::filesystem::path& run_dir) {
  std::vector<std::vector<EpochLosses>> histories;
  histories.reserve(results.size());
  for (const SeedResult& result : results) histories.push_back(result.history);
  DrawTrainingCurves(histories, options.beta,
                     PaperModelName(options) + ", beta " +
                         std::to_string(options.beta).substr(0, 4) + ": loss per scan",
                     run_dir / "training_curves.png");
  const ConvVae model = LoadSeedModel(options, 0, run_dir / "seed_0");
  const std::vector<std::int64_t> picked =
      PickScans(data.test, kReconstructionScans, options.seed, /*near_seam=*/false);
  DrawPolarReconstructions(data.test.index_select(0, torch::tensor(picked)), {model},
                           {PaperModelName(options) + ", seed 0"}, options.transform,
                           "Test scans and mean reconstructions", run_dir / "reconstructions.png");
}

// What a run writes in its folder besides its configuration and log: removed when a new run
// starts there.
std::vector<std::string> RunOutputs(const RunFolder& folder) {
  std::vector<std::string> outputs = {"summary.json", "summary.md", "training_curves.png",
                                      "reconstructions.png"};
  for (const auto& entry : std::filesystem::directory_iterator(folder.path())) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && name.rfind("seed_", 0) == 0) outputs.push_back(name);
  }
  return outputs;
}

int TrainVae(int argc, char** argv) {
  CLI::App app{
      "Pre-trains ShallowConvVAE or DeepConvVAE (paper table, CPTC-1D decoder) on a dataset from\n"
      "generate_dataset: Adam, batch 64, 25 epochs, loss = BCE summed over the 180 rays + beta *\n"
      "KL, Gaussian noise (variance 0.007) on the training split. Per seed k, RUN_DIR/seed_<k>/\n"
      "holds losses.csv, encoder.pt, vae.pt (TorchScript), checkpoint.pt and result.json (test\n"
      "error, active latent dims); rerunning the same command resumes. RUN_DIR/summary.json and\n"
      "summary.md give the test error's mean, sd and Student-t 95 % CI over seeds; figures:\n"
      "training_curves.png, reconstructions.png. The multi-model figures of the paper (zero\n"
      "padding vs CPTC, latent densities) come from the program vae_figures."};
  std::string run_dir;
  bool overwrite = false;
  app.add_option("--out", run_dir, "run folder (created; reused to resume)")->required();
  app.add_flag("--overwrite", overwrite, "replace the run in --out (finished or not)");
  app.footer("\nExit status: 0 finished; 2 bad input (one line naming it, nothing written); " +
             std::to_string(kDivergedStatus) +
             " training diverged\n(NaN or Inf; the last good checkpoint is kept); " +
             std::to_string(kStoppedStatus) +
             " stopped by SIGINT or SIGTERM after an epoch's\ncheckpoint: the same command "
             "continues, under the same configuration, and ends with\nthe files of an "
             "uninterrupted run. A finished run in --out is kept unless --overwrite.\nOne "
             "process writes a run folder at a time (RUN_DIR/.lock).\n");
  const OptionsBinding<VaeTrainingOptions> binding = VaeTrainingBinding();
  ConfigFlags config_flags(app, binding.Schema());
  config_flags.AddFlag("--data", "data.path");
  config_flags.AddFlag("--model", "vae.model");
  config_flags.AddFlag("--latent", "vae.latent_dims");
  config_flags.AddFlag("--beta", "vae.beta");
  config_flags.AddFlag("--decoder-padding", "vae.decoder_padding");
  config_flags.AddFlag("--epochs", "training.epochs");
  config_flags.AddFlag("--seeds", "training.seeds");
  config_flags.AddFlag("--seed", "training.seed");
  config_flags.AddFlag("--batch-size", "training.batch_size");
  config_flags.AddFlag("--lr", "training.learning_rate");
  config_flags.AddFlag("--threads", "training.threads");
  config_flags.AddFlag("--transform", "data.transform");
  ParseCommandLine(app, argc, argv);
  const Config config = config_flags.Resolve();
  const VaeTrainingOptions options = binding.Read(config);
  // The data is checked (every range finite, in [0, 150] m) before the run folder is touched.
  const VaeData data = LoadVaeData(options.data_path, options.transform);

  const RunFolder folder = RunFolder::Create(run_dir);
  const bool continues = !overwrite && std::filesystem::exists(folder.path() / "config.yaml");
  folder.StartNewRun({"summary.json"}, continues ? std::vector<std::string>{} : RunOutputs(folder),
                     overwrite, "replace it with --overwrite");
  if (continues) folder.RequireConfigUnchanged(config, binding.Schema());
  InitLogging("train_vae", folder.LogPath(), false);
  folder.WriteResolvedConfig(config);
  torch::set_num_threads(options.threads);
  const StopFlag stop_flag;

  spdlog::info("{}: train {}, validation {}, test {} scans; {}", options.data_path,
               data.train.size(0), data.validation.size(0), data.test.size(0),
               DescribeVae(options));
  std::vector<SeedResult> results;
  for (std::int64_t k = 0; k < options.seeds; ++k) {
    const std::filesystem::path seed_dir = folder.path() / ("seed_" + std::to_string(k));
    try {
      results.push_back(RunVaeSeed(data, options, k, seed_dir));
    } catch (const TrainingDiverged& diverged) {
      spdlog::error("seed {} diverged: {}; the last good checkpoint is kept in {}", k,
                    diverged.what(), seed_dir.string());
      return kDivergedStatus;
    } catch (const TrainingStopped& stopped) {
      spdlog::info("seed {} {}", k, stopped.what());
      return kStoppedStatus;
    }
    const SeedResult& r = results.back();
    spdlog::info(
        "seed {}: test error {:.3f} (BCE {:.3f} + beta KL {:.3f}), {} active dims, {:.1f} s", k,
        r.test_error, r.test_bce, r.test_kl, r.active_dimensions, r.seconds);
  }
  WriteRunSummary(folder.path(), options, results);
  if (options.figures) DrawRunFigures(data, options, results, folder.path());

  std::vector<double> errors;
  std::vector<double> seconds;
  for (const SeedResult& r : results) {
    errors.push_back(r.test_error);
    seconds.push_back(r.seconds);
  }
  const MeanConfidenceInterval error = Summarise(errors);
  std::printf("%s: test error %.3f [%.3f, %.3f] sd %.3f over %zu seeds\n",
              PaperModelName(options).c_str(), error.mean, error.low, error.high, error.sd,
              errors.size());
  std::printf("seconds_per_seed: %.2f\n", Mean(seconds));
  std::printf("test_error_mean: %.4f\n", error.mean);
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("train_vae", argc, argv, colav::TrainVae);
}

// vae_figures: the paper's multi-model VAE figures, each from small models trained here on a
// generate_dataset file: the zero-padding versus CPTC-1D reconstruction comparison, and the kernel
// density of the test set's 2-D latent for Shallow and Deep with beta in {0, 1, 5}.
#include <ATen/CPUGeneratorImpl.h>
#include <spdlog/spdlog.h>
#include <torch/torch.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <string>
#include <vector>

#include "src/cli.h"
#include "src/finished_output.h"
#include "src/output_path.h"
#include "src/seeding.h"
#include "src/training_diverged.h"
#include "train/vae/config.h"
#include "train/vae/data.h"
#include "train/vae/figures.h"
#include "train/vae/latent_density.h"
#include "train/vae/trainer.h"

namespace colav {
namespace {

constexpr std::int64_t kComparisonScans = 4;

ConvVae TrainLogged(const VaeTrainingOptions& options, const VaeData& data,
                    const std::string& name) {
  const auto start = std::chrono::steady_clock::now();
  ConvVae model = TrainVaeInMemory(options, data, DeriveSeed(options.seed, "vae_figures." + name));
  spdlog::info("trained {} ({}) in {:.1f} s", name, DescribeVae(options),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return model;
}

// The PNG of figure "padding" or "kde" in folder `out`.
std::filesystem::path FigurePath(const std::filesystem::path& out, const std::string& figure) {
  return out / (figure == "padding" ? "padding_comparison.png" : "latent_kde.png");
}

void DrawPaddingComparison(VaeTrainingOptions options, const VaeData& data,
                           const std::filesystem::path& png) {
  options.model = {VaeArchitecture::kShallow, 12, DecoderPadding::kZero};
  const ConvVae zero = TrainLogged(options, data, "zero_padding");
  options.model.decoder_padding = DecoderPadding::kCircular;
  const ConvVae circular = TrainLogged(options, data, "cptc");
  const std::vector<std::int64_t> picked =
      PickScans(data.test, kComparisonScans, options.seed, /*near_seam=*/true);
  DrawPolarReconstructions(data.test.index_select(0, torch::tensor(picked)), {zero, circular},
                           {"zero padding", "CPTC-1D"}, options.transform,
                           "ShallowConvVAE (12) decoders on test scans with an obstacle across the "
                           "seam (dashed)",
                           png);
}

// One sampled z per test scan: the aggregate posterior the paper's density figure shows.
torch::Tensor SampleTestLatents(ConvVae& model, const torch::Tensor& test, std::uint64_t seed) {
  const torch::NoGradGuard no_grad;
  auto [mu, logvar] = model->encoder()->forward(test);
  torch::Generator generator = at::make_generator<at::CPUGeneratorImpl>(seed);
  return mu + torch::randn(mu.sizes(), generator, mu.options()) * torch::exp(0.5 * logvar);
}

void DrawLatentDensities(VaeTrainingOptions options, const VaeData& data,
                         const std::filesystem::path& png) {
  std::vector<DensityPanel> panels;
  for (const VaeArchitecture architecture : {VaeArchitecture::kShallow, VaeArchitecture::kDeep}) {
    for (const double beta : {0.0, 1.0, 5.0}) {
      options.model = {architecture, 2, DecoderPadding::kCircular};
      options.beta = beta;
      const std::string name =
          VaeArchitectureName(architecture) + "_beta" + std::to_string(static_cast<int>(beta));
      ConvVae model = TrainLogged(options, data, name);
      const torch::Tensor z = SampleTestLatents(model, data.test, DeriveSeed(options.seed, name));
      const std::string title =
          std::string(architecture == VaeArchitecture::kShallow ? "Shallow" : "Deep") +
          ", β = " + std::to_string(static_cast<int>(beta));
      panels.push_back({title, GaussianKde2d(z)});
    }
  }
  DrawDensityPanels(panels, 3, "Kernel density of the test set's latent codes (latent size 2)",
                    png);
}

int VaeFigures(int argc, char** argv) {
  CLI::App app{
      "Draws the paper's multi-model VAE figures, training the models they need on DATA.h5:\n"
      "  padding_comparison.png  ShallowConvVAE (latent 12, beta 1) with a zero-padded decoder\n"
      "                          and with CPTC-1D, reconstructing the same test scans\n"
      "  latent_kde.png          Gaussian KDE of the test set's latent codes (latent 2), Shallow\n"
      "                          and Deep with beta 0, 1, 5 (six panels)\n"
      "Eight models of 25 epochs: a few minutes. Other keys as train_vae."};
  std::string out_dir;
  std::vector<std::string> figures = {"padding", "kde"};
  bool overwrite = false;
  app.add_option("--out", out_dir, "folder for the PNG files")->required();
  app.add_flag("--overwrite", overwrite, "redraw figures that --out holds already");
  app.add_option("--figures", figures, "which figures: padding, kde")
      ->check(CLI::IsMember({"padding", "kde"}))
      ->delimiter(',');
  const OptionsBinding<VaeTrainingOptions> binding = VaeTrainingBinding();
  ConfigFlags config_flags(app, binding.Schema());
  config_flags.AddFlag("--data", "data.path");
  config_flags.AddFlag("--epochs", "training.epochs");
  config_flags.AddFlag("--seed", "training.seed");
  config_flags.AddFlag("--threads", "training.threads");
  ParseCommandLine(app, argc, argv);
  const VaeTrainingOptions options = binding.Read(config_flags.Resolve());
  RequireWritableFolder(out_dir, "--out");
  std::vector<std::filesystem::path> outputs;
  outputs.reserve(figures.size());
  for (const std::string& figure : figures) outputs.push_back(FigurePath(out_dir, figure));
  RefuseToReplaceFinishedOutput(outputs, "--out", overwrite);
  torch::set_num_threads(options.threads);

  const VaeData data = LoadVaeData(options.data_path, options.transform);
  try {
    for (const std::string& figure : figures) {
      if (figure == "padding") DrawPaddingComparison(options, data, FigurePath(out_dir, figure));
      if (figure == "kde") DrawLatentDensities(options, data, FigurePath(out_dir, figure));
    }
  } catch (const TrainingDiverged& diverged) {
    spdlog::error("training diverged: {}", diverged.what());
    return kDivergedStatus;
  }
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("vae_figures", argc, argv, colav::VaeFigures);
}

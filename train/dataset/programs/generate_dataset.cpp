// generate_dataset: records range scans (simulator under a scripted pilot + synthetic scenes),
// augments them with random circular shifts, splits them by source scan and writes one HDF5 file
// (layout in train/dataset/file.h).
#include <CLI/CLI.hpp>
#include <array>
#include <chrono>
#include <cstdio>
#include <string>

#include "src/cli.h"
#include "src/finished_output.h"
#include "src/output_path.h"
#include "src/progress.h"
#include "train/dataset/config.h"
#include "train/dataset/file.h"
#include "train/dataset/generation.h"

namespace colav {
namespace {

void PrintComposition(const ScanDataset& dataset) {
  std::array<std::array<std::int64_t, 3>, kNumScanGroups> counts{};
  for (std::size_t row = 0; row < dataset.rows(); ++row) {
    ++counts[static_cast<std::size_t>(dataset.group[row])]
            [static_cast<std::size_t>(dataset.split[row])];
  }
  std::printf("%-34s %8s %8s %8s\n", "rows by group", "train", "val", "test");
  for (int g = 0; g < kNumScanGroups; ++g) {
    const auto& c = counts[static_cast<std::size_t>(g)];
    std::printf("%-34s %8lld %8lld %8lld\n", ScanGroupName(static_cast<ScanGroup>(g)).c_str(),
                static_cast<long long>(c[0]), static_cast<long long>(c[1]),
                static_cast<long long>(c[2]));
  }
}

int GenerateDataset(int argc, char** argv) {
  CLI::App app{
      "Records range scans for VAE pre-training into one HDF5 file: scans of the paper's training\n"
      "environment while a scripted line-of-sight pilot drives (with varied thrust, noise and\n"
      "evasive turns), and synthetic scans (3 circles + 2 vessels, 5 vessels, 5 circles). Every\n"
      "scan gets random circular shifts; the split train/validation/test is by source scan.\n"
      "Datasets: ranges [N,180] (m, 150 = no return), group, source_scan, shift, split;\n"
      "attributes config, seed, description."};
  std::string out_path;
  bool overwrite = false;
  app.add_option("--out", out_path, "dataset file to write (HDF5)")->required();
  app.add_flag("--overwrite", overwrite, "replace an existing dataset file");
  const OptionsBinding<DatasetGenerationOptions> binding = DatasetGenerationBinding();
  ConfigFlags config_flags(app, binding.Schema());
  config_flags.AddFlag("--sim-scans", "dataset.sim_scans");
  config_flags.AddFlag("--synthetic-scans", "dataset.synthetic_scans");
  config_flags.AddFlag("--seed", "dataset.seed");
  config_flags.AddFlag("--threads", "dataset.threads");
  ParseCommandLine(app, argc, argv);
  const Config config = config_flags.Resolve();
  const DatasetGenerationOptions options = binding.Read(config);
  RequireWritableFile(out_path, "--out");
  RefuseToReplaceFinishedOutput({out_path}, "--out", overwrite);

  const auto start = std::chrono::steady_clock::now();
  ProgressBar progress("scans", options.sim_scans + options.synthetic_scans, "scans");
  ScanDataset dataset =
      GenerateScanDataset(options, [&](std::int64_t done) { progress.Update(done); });
  progress.Finish();
  dataset.config = config.ToYaml();
  WriteScanDataset(dataset, out_path);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  PrintComposition(dataset);
  std::printf("wrote %s (%zu rows)\n", out_path.c_str(), dataset.rows());
  std::printf("generation_seconds: %.2f\n", seconds);
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("generate_dataset", argc, argv, colav::GenerateDataset);
}

// plot_training: the paper's four-panel training-curve figure from train_ppo run folders.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "eval/labelled_argument.h"
#include "eval/training_curves.h"
#include "src/cli.h"
#include "src/number_flag.h"
#include "src/output_path.h"

namespace colav {
namespace {

constexpr std::size_t kSeedCurvePoints = 300;  // enough for a smooth line at the figure's width

// One curve per label, in the order labels first appear.
std::vector<TrainingCurve> SeedCurves(const std::vector<TrainingRun>& runs, std::size_t window) {
  std::vector<std::string> labels;
  for (const TrainingRun& run : runs) {
    if (std::find(labels.begin(), labels.end(), run.label) == labels.end()) {
      labels.push_back(run.label);
    }
  }
  std::vector<TrainingCurve> curves;
  for (const std::string& label : labels) {
    std::vector<TrainingRun> seeds;
    std::copy_if(runs.begin(), runs.end(), std::back_inserter(seeds),
                 [&](const TrainingRun& run) { return run.label == label; });
    curves.push_back(SeedCurve(seeds, window, kSeedCurvePoints));
  }
  return curves;
}

std::string RangeOverSeedsBand(std::size_t window) {
  return "mean over seeds of the rolling mean over " + std::to_string(window) +
         " episodes, range over seeds shaded";
}

int PlotTraining(int argc, char** argv) {
  CLI::App app{
      "Draws path progress, cross-track error, duration and collision rate of the training\n"
      "episodes (RUN_DIR/episodes.csv of train_ppo) against environment steps: rolling mean over\n"
      "the last --window episodes, shaded rolling standard deviation, one colour per run.\n"
      "With --over-seeds, runs given the same LABEL are the seeds of one configuration: one line\n"
      "per label, the mean over its seeds of their rolling means, the range over seeds shaded.\n"
      "Runs still training can be drawn: their last, half-written line is ignored."};
  std::vector<std::string> run_arguments;
  std::string out;
  std::string title = "Training";
  std::uint64_t window = 100;
  bool over_seeds = false;
  app.add_option("--run", run_arguments,
                 "[LABEL=]RUN_DIR of train_ppo, repeatable (label: folder name)")
      ->required();
  app.add_option("--out", out, "PNG to write")->required();
  app.add_option("--title", title, "figure title");
  AddNumberFlag<std::uint64_t>(app, "--window", window, "episodes in the rolling window", 1,
                               1'000'000);
  app.add_flag("--over-seeds", over_seeds,
               "one line per LABEL: mean over the runs sharing it, band = range over them");
  const ConfigFlags config_flags(app, ConfigSchema());  // no keys; --print-config as everywhere
  ParseCommandLine(app, argc, argv);
  config_flags.Resolve();  // no keys: rejects any in --set or --config
  RequireWritableFile(out, "--out");

  std::vector<TrainingRun> runs;
  for (const std::string& argument : run_arguments) {
    const LabelledArgument run = ParseLabelledArgument(argument, "--run");
    const std::filesystem::path dir(run.value);
    const std::string label = run.label.value_or(
        dir.filename().empty() ? dir.parent_path().filename().string() : dir.filename().string());
    runs.push_back(ReadTrainingRun(label, dir / "episodes.csv"));
  }
  if (over_seeds) {
    PlotTrainingCurves(SeedCurves(runs, window), title, RangeOverSeedsBand(window), out);
  } else {
    std::vector<TrainingCurve> curves;
    curves.reserve(runs.size());
    for (const TrainingRun& run : runs) curves.push_back(RollingCurve(run, window));
    PlotTrainingCurves(curves, title,
                       "rolling mean and sd over " + std::to_string(window) + " episodes", out);
  }
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("plot_training", argc, argv, colav::PlotTraining);
}

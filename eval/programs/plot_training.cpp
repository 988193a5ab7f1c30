// plot_training: the paper's four-panel training-curve figure from train_ppo run folders.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "eval/labelled_argument.h"
#include "eval/training_curves.h"
#include "src/cli.h"
#include "src/number_flag.h"
#include "src/output_path.h"

namespace colav {
namespace {

int PlotTraining(int argc, char** argv) {
  CLI::App app{
      "Draws path progress, cross-track error, duration and collision rate of the training\n"
      "episodes (RUN_DIR/episodes.csv of train_ppo) against environment steps: rolling mean over\n"
      "the last --window episodes, shaded rolling standard deviation, one colour per run.\n"
      "Runs still training can be drawn: their last, half-written line is ignored."};
  std::vector<std::string> run_arguments;
  std::string out;
  std::string title = "Training";
  std::uint64_t window = 100;
  app.add_option("--run", run_arguments,
                 "[LABEL=]RUN_DIR of train_ppo, repeatable (label: folder name)")
      ->required();
  app.add_option("--out", out, "PNG to write")->required();
  app.add_option("--title", title, "figure title");
  AddNumberFlag<std::uint64_t>(app, "--window", window, "episodes in the rolling window", 1,
                               1'000'000);
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
  PlotTrainingCurves(runs, window, title, out);
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("plot_training", argc, argv, colav::PlotTraining);
}

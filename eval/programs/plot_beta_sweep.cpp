// plot_beta_sweep: final test metrics against the VAE's beta, from evaluate summaries.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "eval/beta_sweep_figure.h"
#include "eval/evaluation_report.h"
#include "eval/labelled_argument.h"
#include "src/atomic_file.h"
#include "src/cli.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/output_path.h"

namespace colav {
namespace {

double ParseBeta(const std::string& text, const std::string& argument) {
  const std::optional<double> beta = ParseFiniteNumber(text);
  if (!beta || *beta < 0.0) {
    throw UserError("--model '" + argument + "': beta '" + text + "' is not a number >= 0");
  }
  return *beta;
}

const ModelSummary& FindModel(const std::vector<ModelSummary>& models, const std::string& name,
                              const std::string& argument) {
  for (const ModelSummary& model : models) {
    if (model.name == name) return model;
  }
  throw UserError("--model '" + argument + "': no model '" + name + "' in the --summary files");
}

int PlotBetaSweepProgram(int argc, char** argv) {
  CLI::App app{
      "Draws the beta sweep: progress, cross-track error, duration and collision rate on the test\n"
      "scenarios (mean and 95 % CI from evaluate's summary.json) against the beta the agent's\n"
      "VAE encoder was pre-trained with; optionally the same as a Markdown table."};
  std::vector<std::string> summaries;
  std::vector<std::string> model_arguments;
  std::string out;
  std::string table;
  std::string title = "Beta sweep: test metrics against beta";
  app.add_option("--summary", summaries, "summary.json of evaluate, repeatable")->required();
  app.add_option("--model", model_arguments,
                 "NAME=BETA: a model of the summaries and its beta, repeatable")
      ->required();
  app.add_option("--out", out, "PNG to write")->required();
  app.add_option("--table", table, "also write the Markdown table here");
  app.add_option("--title", title, "figure title");
  const ConfigFlags config_flags(app, ConfigSchema());  // no keys; --print-config as everywhere
  ParseCommandLine(app, argc, argv);
  config_flags.Resolve();  // no keys: rejects any in --set or --config
  RequireWritableFile(out, "--out");
  if (!table.empty()) RequireWritableFile(table, "--table");

  std::vector<ModelSummary> models;
  for (const std::string& summary : summaries) {
    for (ModelSummary& model : ReadModelSummaries(summary)) models.push_back(std::move(model));
  }
  std::vector<BetaSweepPoint> points;
  for (const std::string& argument : model_arguments) {
    const LabelledArgument parsed = ParseLabelledArgument(argument, "--model");
    if (!parsed.label) throw UserError("--model '" + argument + "': expected NAME=BETA");
    points.push_back(
        {ParseBeta(parsed.value, argument), FindModel(models, *parsed.label, argument)});
  }
  PlotBetaSweep(points, title, out);
  if (!table.empty()) WriteTextFileAtomically(table, BetaSweepTable(points));
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("plot_beta_sweep", argc, argv, colav::PlotBetaSweepProgram);
}

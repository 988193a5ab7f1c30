// simulate: replays a scenario file under an action sequence and writes the per-step trace
// (shared/spec/interfaces.md), optionally a picture of the scene and a replay (HTML, GIF, MP4).
#include <CLI/CLI.hpp>
#include <iostream>
#include <limits>

#include "env/environment.h"
#include "env/environment_config.h"
#include "env/scenario_file.h"
#include "env/scene_plot.h"
#include "env/trace.h"
#include "env/training_scenario.h"
#include "eval/replay/replay_flags.h"
#include "eval/replay/replay_recorder.h"
#include "src/atomic_file.h"
#include "src/cli.h"
#include "src/error.h"
#include "src/number_flag.h"
#include "src/output_path.h"

namespace colav {
namespace {

// The scenario of --scenario or --training-seed.
Scenario ChosenScenario(const std::string& scenario_path, const CLI::Option& seed_option,
                        std::uint64_t training_seed) {
  if (scenario_path.empty() && seed_option.count() == 0) {
    throw UserError("give a scenario: --scenario FILE.yaml or --training-seed S");
  }
  return seed_option.count() > 0 ? TrainingScenarioGenerator().Make(training_seed)
                                 : LoadScenarioFile(scenario_path);
}

int Simulate(int argc, char** argv) {
  CLI::App app{
      "Replays a scenario file under a given action sequence and writes a per-step trace:\n"
      "row 0 = the state after reset, then one row per action, stopping when the episode\n"
      "terminates or is truncated. Columns: step, vessel state, guidance errors, progress,\n"
      "reward, flags and the 180 ranges (m)."};
  std::string scenario_path;
  std::string actions_path;
  std::string trace_path;
  std::string plot_path;
  std::uint64_t training_seed = 0;
  std::string save_scenario_path;
  auto* scenario_option = app.add_option("--scenario", scenario_path, "scenario file (YAML)");
  auto* seed_option =
      AddNumberFlag<std::uint64_t>(app, "--training-seed", training_seed,
                                   "instead of --scenario: the paper's training world of this seed",
                                   0, std::numeric_limits<std::uint64_t>::max());
  scenario_option->excludes(seed_option);
  app.add_option("--save-scenario", save_scenario_path,
                 "also write the scenario as a scenario file (e.g. to edit a training world)");
  app.add_option("--actions", actions_path, "actions file: header a0,a1, one row per step")
      ->required();
  app.add_option("--out", trace_path, "trace file to write (CSV; an existing one is replaced)")
      ->required();
  app.add_option("--plot", plot_path, "also draw the scene and the track to this PNG");
  ReplayFlags replay_flags(app);
  const OptionsBinding<EnvironmentConfig> binding = EnvironmentBinding();
  const ConfigFlags config_flags(app, binding.Schema());
  ParseCommandLine(app, argc, argv);
  const EnvironmentConfig env_config = binding.Read(config_flags.Resolve());

  // Every input and output path is checked before anything is written.
  const Scenario scenario = ChosenScenario(scenario_path, *seed_option, training_seed);
  const auto actions = LoadActionsFile(actions_path);
  RequireWritableFile(trace_path, "--out");
  if (!save_scenario_path.empty()) RequireWritableFile(save_scenario_path, "--save-scenario");
  if (!plot_path.empty()) RequireWritableFile(plot_path, "--plot");
  replay_flags.Check();

  Environment env(env_config, std::make_shared<FixedScenarioSource>(scenario));
  std::vector<float> observation(ObservationSize(env_config));
  env.Reset(0, observation.data());
  std::string trace = TraceHeader() + "\n" + TraceRow(0, env.world(), StepResult{}) + "\n";
  SceneTrack track{"vessel", {env.world().vessel().head<2>()}, {}, false};
  std::optional<ReplayRecorder> recorder;
  if (replay_flags.wanted()) {
    recorder.emplace(env.world(), scenario.name,
                     std::filesystem::path(actions_path).stem().string());
  }
  std::int64_t step = 0;
  for (const auto& action : actions) {
    const StepResult result = env.Step(action.data(), observation.data());
    trace += TraceRow(++step, env.world(), result) + "\n";
    if (recorder) recorder->Record(env.world(), action.data(), result);
    track.positions.emplace_back(env.world().vessel().head<2>());
    track.collision = result.collision;
    if (result.terminated || result.truncated) break;
  }
  if (!save_scenario_path.empty()) {
    WriteTextFileAtomically(save_scenario_path, ScenarioToYaml(scenario));
  }
  WriteTextFileAtomically(trace_path, trace);
  if (!plot_path.empty()) {
    PlotScene(scenario, {track}, step, plot_path,
              scenario.name + " (" + std::to_string(step) + " steps)");
  }
  if (recorder) replay_flags.Write(recorder->replay());
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("simulate", argc, argv, colav::Simulate);
}

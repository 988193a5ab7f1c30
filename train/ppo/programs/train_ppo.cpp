// train_ppo: trains the PPO collision-avoidance agent with a chosen feature extractor (spec
// interfaces.md). Outputs in RUN_DIR: policy.pt, training_state.pt, checkpoints/, episodes.csv,
// updates.csv, summary.json, config.yaml, train_ppo.log; ends with the headline lines
// `steps_per_s: N` and `wall_s: N`.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cstring>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "models/actor_critic.h"
#include "src/cli.h"
#include "src/error.h"
#include "src/logging.h"
#include "src/run_folder.h"
#include "src/training_diverged.h"
#include "train/ppo/checkpoint.h"
#include "train/ppo/config.h"
#include "train/ppo/encoder_check.h"
#include "train/ppo/trainer.h"
#include "train/ppo/update.h"

namespace {

// What a run writes besides its configuration and log: removed when a new run starts in a folder.
const std::vector<std::string> kRunOutputs = {"policy.pt",    "training_state.pt", "checkpoints",
                                              "episodes.csv", "updates.csv",       "summary.json"};

// A resumed run reads its configuration from RUN_DIR/config.yaml unless --config says otherwise:
// inserts "--config RUN_DIR/config.yaml" after the program name.
std::vector<std::string> WithRunConfig(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  std::string resume_dir;
  bool has_config = false;
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--config" || args[i].rfind("--config=", 0) == 0) has_config = true;
    if (args[i] == "--resume" && i + 1 < args.size()) resume_dir = args[i + 1];
    if (args[i].rfind("--resume=", 0) == 0) resume_dir = args[i].substr(std::strlen("--resume="));
  }
  if (!resume_dir.empty() && !has_config) {
    args.insert(args.begin() + 1, {"--config", resume_dir + "/config.yaml"});
  }
  return args;
}

// A resumed run continues with the configuration its checkpoint was trained with (state files
// from before it was recorded: with its config.yaml). The thread count does not change results
// (the worlds step the same on any number); the deterministic action only shapes the exported
// policy.pt (a finished run exports it again).
void RequireRunConfig(const colav::RunFolder& run, const colav::Config& config,
                      const colav::ConfigSchema& schema) {
  const std::vector<std::string> free_keys = {"train.env_threads",
                                              "policy.deterministic_thrust_std_scale",
                                              "policy.deterministic_moment_std_scale"};
  const std::optional<std::string> recorded = colav::RecordedConfig(run.path());
  if (!recorded) {
    run.RequireConfigUnchanged(config, schema, free_keys);
    return;
  }
  const std::string source = colav::TrainingStatePath(run.path()).string();
  run.RequireConfigUnchanged(config, colav::Config::FromYamlText(schema, *recorded, source), source,
                             free_keys);
}

int Main(int argc, char** argv) {
  CLI::App app{"Trains the PPO collision-avoidance agent (Stable-Baselines3 semantics)."};
  const colav::OptionsBinding<colav::PpoRunOptions> binding = colav::PpoRunBinding();
  colav::ConfigFlags config_flags(app, binding.Schema());
  config_flags.AddFlag("--extractor", "extractor.name");
  config_flags.AddFlag("--encoder", "extractor.encoder");
  config_flags.AddSwitch("--locked", "extractor.locked", true, "freeze the pre-trained encoder");
  config_flags.AddSwitch("--unlocked", "extractor.locked", false, "fine-tune the encoder");
  config_flags.AddFlag("--encoder-closeness", "extractor.encoder_closeness");
  config_flags.AddFlag("--steps", "ppo.total_steps");
  config_flags.AddFlag("--envs", "ppo.n_envs");
  config_flags.AddFlag("--seed", "train.seed");
  std::string out;
  std::string resume;
  bool overwrite = false;
  bool verbose = false;
  app.add_option("--out", out, "run folder (created)")->type_name("RUN_DIR");
  app.add_option("--resume", resume, "continue the run in RUN_DIR from its last checkpoint")
      ->type_name("RUN_DIR");
  app.add_flag("--overwrite", overwrite, "replace the run already in --out")->excludes("--resume");
  app.footer("\nExit status: 0 finished; 2 bad input (one line naming it, nothing written); " +
             std::to_string(colav::kDivergedStatus) +
             " training diverged\n(NaN or Inf; the last good checkpoint is kept); " +
             std::to_string(colav::kStoppedStatus) +
             " stopped by SIGINT or SIGTERM after a checkpoint:\n--resume RUN_DIR continues and "
             "ends with the files of an uninterrupted run. One process\nwrites a run folder at a "
             "time (RUN_DIR/.lock).\n" +
             app.get_footer());
  app.add_flag("-v,--verbose", verbose, "debug logging");

  std::vector<std::string> args = WithRunConfig(argc, argv);
  std::vector<char*> arg_pointers;
  arg_pointers.reserve(args.size());
  for (std::string& arg : args) arg_pointers.push_back(arg.data());
  colav::ParseCommandLine(app, static_cast<int>(arg_pointers.size()), arg_pointers.data());
  if (out.empty() && resume.empty()) throw colav::UserError("--out RUN_DIR is required");
  if (!out.empty() && !resume.empty() && out != resume) {
    throw colav::UserError("--out " + out + " and --resume " + resume + " name different runs");
  }
  const std::string run_path = resume.empty() ? out : resume;
  if (!resume.empty() &&
      !std::filesystem::is_regular_file(std::filesystem::path(resume) / "training_state.pt")) {
    throw colav::UserError("--resume " + resume + ": no training_state.pt in that folder");
  }
  const colav::Config config = config_flags.Resolve();
  const colav::PpoRunOptions options = binding.Read(config);
  // A bad extractor setting, encoder or policy.init file fails here, before the run folder is
  // touched.
  if (resume.empty()) {
    colav::CheckEncoderObservationSettings(options);
    colav::InitialPolicy(options);
  }

  const colav::RunFolder run = colav::RunFolder::Create(run_path);
  if (resume.empty()) {
    run.StartNewRun({"training_state.pt", "summary.json"}, kRunOutputs, overwrite,
                    "continue it with --resume " + run_path + ", or replace it with --overwrite");
  } else {
    RequireRunConfig(run, config, binding.Schema());
  }
  colav::InitLogging("train_ppo", run.LogPath(), verbose);
  run.WriteResolvedConfig(config);
  // The networks are far too small for intra-op threads; idle OpenMP workers would only compete
  // with the environment's threads.
  torch::set_num_threads(1);
  try {
    const colav::PpoRunSummary summary =
        colav::TrainPpo(options, config.ToJson(), run.path(), !resume.empty());
    const colav::RollingEpisodeStats& r = summary.rolling;
    spdlog::info(
        "{} at step {}: last {} episodes progress {:.1f}%, cte {:.1f} m, {:.0f} steps, "
        "collisions {:.1f}%",
        summary.finished ? "finished" : "stopped", summary.counters.global_step, r.count,
        100 * r.progress, r.mean_cte, r.steps, 100 * r.collision_rate);
    std::cout << "steps_per_s: " << summary.steps_per_s << "\n"
              << "wall_s: " << summary.wall_s << std::endl;
    if (!summary.finished) {
      spdlog::info("stopped on request; --resume {} continues", run_path);
      return colav::kStoppedStatus;
    }
  } catch (const colav::TrainingDiverged& diverged) {
    spdlog::error("training diverged: {}; the last good checkpoint is kept in {}", diverged.what(),
                  run_path);
    return colav::kDivergedStatus;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return colav::RunProgram("train_ppo", argc, argv, Main); }

// evaluate: runs trained policies with deterministic actions on the shared test scenarios (or on
// scenario files) and writes episodes.csv, summary.json, summary.md and trajectory figures.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>

#include "env/environment_config.h"
#include "env/observation_settings.h"
#include "eval/collision_analysis.h"
#include "eval/episode_runner.h"
#include "eval/episode_table.h"
#include "eval/evaluation_episodes.h"
#include "eval/evaluation_report.h"
#include "eval/policy.h"
#include "eval/policy_fingerprint.h"
#include "eval/replay/replay_page.h"
#include "eval/replay/replay_recorder.h"
#include "eval/reused_episodes.h"
#include "eval/safe_name.h"
#include "eval/trajectory_figure.h"
#include "src/atomic_file.h"
#include "src/build_id.h"
#include "src/cli.h"
#include "src/error.h"
#include "src/logging.h"
#include "src/number_flag.h"
#include "src/progress.h"
#include "src/run_folder.h"
#include "src/threads/thread_pool.h"

namespace colav {
namespace {

struct EvaluateOptions {
  EnvironmentConfig env;
  int episodes = 100;
  std::uint64_t seed = 0;
  int threads = 0;  ///< 0: all cores
  int trajectory_scenarios = 3;
  int trajectory_starts = 5;
  /// Scenario files drawn, the first ones: a figure per file and model costs about 40 ms, so a
  /// thousand generated files would spend minutes drawing.
  int scenario_file_figures = 100;
};

OptionsBinding<EvaluateOptions> EvaluateBinding() {
  using Options = EvaluateOptions;
  // The environment in test mode by default: evaluation follows the reference test procedure,
  // which has no cumulative-reward floor.
  Options defaults;
  defaults.env.test_mode = true;
  OptionsBinding<Options> binding(defaults);
  binding.Include(EnvironmentBinding(), &Options::env)
      .Number("eval.episodes", &Options::episodes, "number of test scenarios", 1, 100000)
      .Number("eval.seed", &Options::seed,
              "master seed of the test scenarios (shared by every model)", 0)
      .Number("eval.threads", &Options::threads, "threads stepping the episodes (0 = all cores)", 0,
              256)
      .Number("eval.trajectory_scenarios", &Options::trajectory_scenarios,
              "test scenarios drawn as trajectory figures (the first ones)", 0, 100000)
      .Number("eval.trajectory_starts", &Options::trajectory_starts,
              "runs per model in each trajectory figure: the test start plus perturbed starts", 1,
              100)
      .Number("eval.scenario_file_figures", &Options::scenario_file_figures,
              "with --scenario: files drawn as trajectory figures, one per model (the first ones)",
              0, 100000);
  return binding;
}

std::vector<Policy> LoadPolicies(const std::vector<std::string>& paths,
                                 const std::vector<std::string>& names) {
  if (!names.empty() && names.size() != paths.size()) {
    throw UserError("--name: " + std::to_string(names.size()) + " names for " +
                    std::to_string(paths.size()) + " policies");
  }
  std::vector<Policy> policies;
  for (std::size_t m = 0; m < paths.size(); ++m) {
    const std::string name = names.empty() ? DefaultPolicyName(paths[m]) : names[m];
    RequireSafeName(name, names.empty() ? paths[m] : "--name");
    for (const Policy& other : policies) {
      if (other.name() == name) {
        throw UserError(paths[m] + ": model name '" + name + "' is already used by " +
                        other.path().string() + " (give --name)");
      }
    }
    policies.emplace_back(paths[m], name);
  }
  return policies;
}

// Logs, per policy, the observation settings it runs under and where they come from (a warning
// when neither its file nor a sidecar says) and
// returns them as "closeness log (recorded in the file)" for the report.
std::vector<std::string> ObservationSettingsLines(const std::vector<Policy>& policies,
                                                  const EnvironmentConfig& env) {
  const ObservationSettings configured = ObservationSettingsOf(env);
  std::vector<std::string> lines;
  for (const Policy& policy : policies) {
    const ObservationSettings used = policy.SettingsOr(configured);
    lines.push_back(DescribeObservationSettings(used) + " (" +
                    (policy.own_settings() ? policy.settings_origin() : "evaluation config") + ")");
    if (!policy.own_settings()) {
      spdlog::warn(
          "{}: {} records no observation settings and has no sidecar {}; running it under "
          "the evaluation's {}",
          policy.name(), policy.path().string(), SidecarPath(policy.path()).string(),
          DescribeObservationSettings(used));
    } else if (used != configured) {
      spdlog::info("{}: runs under its own {} ({}), not the evaluation's {}", policy.name(),
                   DescribeObservationSettings(used), policy.settings_origin(),
                   DescribeObservationSettings(configured));
    } else {
      spdlog::info("{}: {} ({})", policy.name(), DescribeObservationSettings(used),
                   policy.settings_origin());
    }
  }
  return lines;
}

std::vector<std::vector<EpisodeOutcome>> RunWithProgress(
    std::vector<Policy>& policies, const std::vector<EvaluationEpisode>& episodes,
    const EnvironmentConfig& env_config, int threads, const std::string& label) {
  ProgressBar progress(label, static_cast<std::int64_t>(policies.size() * episodes.size()),
                       "episodes");
  auto outcomes = RunEpisodes(policies, episodes, env_config, threads,
                              [&](int finished, int) { progress.Update(finished); });
  progress.Finish();
  return outcomes;
}

// Settings that change no test episode: an earlier evaluation that differs only in them may lend
// its episodes (--reuse).
const std::vector<std::string> kSettingsBesideEpisodes = {
    "eval.threads", "eval.trajectory_scenarios", "eval.trajectory_starts",
    "eval.scenario_file_figures"};

// outcomes[m][e] of every policy: the metrics `reusable` holds for it, else its episodes run.
std::vector<std::vector<EpisodeOutcome>> RunUnlessReusable(
    const std::vector<Policy>& policies, const std::vector<EvaluationEpisode>& episodes,
    const ReusableEpisodes& reusable, const EnvironmentConfig& env_config, int threads) {
  std::vector<std::vector<EpisodeOutcome>> outcomes(policies.size());
  std::vector<Policy> to_run;
  std::vector<std::size_t> run_index;
  for (std::size_t m = 0; m < policies.size(); ++m) {
    const auto taken = reusable.by_model.find(policies[m].name());
    if (taken == reusable.by_model.end()) {
      to_run.push_back(policies[m]);
      run_index.push_back(m);
      continue;
    }
    for (const EpisodeMetrics& metrics : taken->second) {
      outcomes[m].emplace_back().metrics = metrics;
    }
  }
  if (to_run.empty()) return outcomes;
  auto ran = RunWithProgress(to_run, episodes, env_config, threads, "evaluate");
  for (std::size_t i = 0; i < run_index.size(); ++i) outcomes[run_index[i]] = std::move(ran[i]);
  return outcomes;
}

// What --reuse FOLDER lends this evaluation (nothing without the flag).
ReusableEpisodes LookForReusableEpisodes(const std::string& folder, const Config& config,
                                         const ConfigSchema& schema,
                                         const std::vector<Policy>& policies,
                                         const std::vector<std::string>& fingerprints,
                                         const std::vector<EvaluationEpisode>& episodes) {
  if (folder.empty()) return {};
  std::map<std::string, std::string> by_name;
  for (std::size_t m = 0; m < policies.size(); ++m) by_name[policies[m].name()] = fingerprints[m];
  const PlannedEvaluation planned{config, schema, kSettingsBesideEpisodes, ProgramBuildId(),
                                  episodes};
  return FindReusableEpisodes(folder, planned, by_name);
}

void LogReuse(const std::string& folder, const ReusableEpisodes& reusable, std::size_t models) {
  if (folder.empty()) return;
  if (reusable.by_model.empty()) {
    spdlog::info("--reuse: nothing taken ({})", reusable.why_none);
    return;
  }
  std::vector<std::string> names;
  for (const auto& [name, metrics] : reusable.by_model) names.push_back(name);
  spdlog::info(
      "--reuse: the episodes of {} of {} model(s) taken from {} (same settings, scenarios and "
      "policy files): {}",
      names.size(), models, folder, fmt::format("{}", fmt::join(names, ", ")));
}

std::vector<std::vector<EpisodeMetrics>> MetricsOf(
    const std::vector<std::vector<EpisodeOutcome>>& outcomes) {
  std::vector<std::vector<EpisodeMetrics>> metrics(outcomes.size());
  for (std::size_t m = 0; m < outcomes.size(); ++m) {
    for (const EpisodeOutcome& outcome : outcomes[m]) metrics[m].push_back(outcome.metrics);
  }
  return metrics;
}

// One picture per model of the single run in each of the first `pictured` scenario files.
void PlotScenarioFileRuns(const std::vector<Policy>& policies,
                          const std::vector<EvaluationEpisode>& episodes,
                          const std::vector<std::vector<EpisodeOutcome>>& outcomes, int pictured,
                          const std::filesystem::path& out) {
  const std::size_t files = std::min<std::size_t>(pictured, episodes.size());
  for (std::size_t e = 0; e < files; ++e) {
    for (std::size_t m = 0; m < policies.size(); ++m) {
      PlotTrajectories(episodes[e].scenario, episodes[e].name, policies[m].name(), {outcomes[m][e]},
                       {policies[m].name()},
                       TrajectoryFigurePath(out, episodes[e].name, policies[m].name()));
    }
  }
}

// The paper's trajectory figure: for the first test scenarios, each model from the test start and
// from perturbed starts, one picture per scenario and model.
void PlotTestTrajectories(std::vector<Policy>& policies,
                          const std::vector<EvaluationEpisode>& episodes,
                          const std::vector<std::vector<EpisodeOutcome>>& outcomes,
                          const EvaluateOptions& options, int threads,
                          const std::filesystem::path& out) {
  const int pictured =
      std::min<int>(options.trajectory_scenarios, static_cast<int>(episodes.size()));
  const int starts = options.trajectory_starts;
  const std::uint64_t seed = options.seed;
  std::vector<EvaluationEpisode> perturbed;  // scenario e's start s at e * (starts - 1) + s - 1
  for (int e = 0; e < pictured; ++e) {
    for (int s = 1; s < starts; ++s) perturbed.push_back(WithPerturbedStart(episodes[e], seed, s));
  }
  // A separate batch, so the test episodes' results do not depend on the figure settings.
  const auto perturbed_outcomes =
      perturbed.empty()
          ? std::vector<std::vector<EpisodeOutcome>>(policies.size())
          : RunWithProgress(policies, perturbed, options.env, threads, "trajectory starts");
  std::vector<std::string> labels = {"test start"};
  for (int s = 1; s < starts; ++s) labels.push_back("start " + std::to_string(s));
  for (int e = 0; e < pictured; ++e) {
    for (std::size_t m = 0; m < policies.size(); ++m) {
      std::vector<EpisodeOutcome> runs = {outcomes[m][e]};
      for (int s = 1; s < starts; ++s) {
        runs.push_back(perturbed_outcomes[m][e * (starts - 1) + s - 1]);
      }
      PlotTrajectories(episodes[e].scenario, episodes[e].name, policies[m].name(), runs, labels,
                       TrajectoryFigurePath(out, episodes[e].name, policies[m].name()));
    }
  }
}

// Which episodes --replay writes, and how they are chosen.
struct ReplayChoice {
  bool enabled = false;
  int first = 3;     ///< the first test scenarios
  int collided = 3;  ///< and the first other test scenarios in which some model collided
};

bool SomeModelCollided(const std::vector<std::vector<EpisodeOutcome>>& outcomes,
                       std::size_t episode) {
  return std::any_of(outcomes.begin(), outcomes.end(),
                     [&](const auto& model) { return model[episode].metrics.collision; });
}

// Indices of the episodes to replay: every scenario file; of the test scenarios, the first
// `first` and then the first `collided` others in which some model collided.
std::vector<int> ReplayedEpisodes(const ReplayChoice& choice, bool on_files,
                                  const std::vector<std::vector<EpisodeOutcome>>& outcomes) {
  const int count = outcomes.empty() ? 0 : static_cast<int>(outcomes.front().size());
  std::vector<int> chosen;
  int collided = 0;
  for (int e = 0; e < count; ++e) {
    if (on_files || e < choice.first) {
      chosen.push_back(e);
    } else if (SomeModelCollided(outcomes, e) && collided < choice.collided) {
      chosen.push_back(e);
      ++collided;
    }
  }
  return chosen;
}

// OUT/replays/<episode>.html: each chosen episode with every model's run, re-run with recording
// (a model's episode does not depend on the batch it runs in, so these are the evaluated runs).
void WriteReplays(std::vector<Policy>& policies, const std::vector<EvaluationEpisode>& episodes,
                  const std::vector<int>& chosen, const EnvironmentConfig& env, int threads,
                  const std::filesystem::path& out) {
  std::vector<EvaluationEpisode> replayed;
  replayed.reserve(chosen.size());
  for (const int e : chosen) replayed.push_back(episodes[e]);
  auto outcomes = RunEpisodes(policies, replayed, env, threads, {}, /*record_replays=*/true);
  for (std::size_t e = 0; e < replayed.size(); ++e) {
    std::vector<Replay> runs;
    runs.reserve(outcomes.size());
    for (auto& model : outcomes) runs.push_back(std::move(*model[e].replay));
    WriteReplayPage(CombineRuns(std::move(runs)), out / "replays" / (replayed[e].name + ".html"));
  }
  spdlog::info("wrote {} replay page(s) to {}", replayed.size(), (out / "replays").string());
}

// OUT/collisions.csv and OUT/collisions.md: every collision of every model, replayed from the
// actions of its evaluation run, the obstacle named and avoidance searched.
void AnalyseCollisions(const std::vector<Policy>& policies,
                       const std::vector<EvaluationEpisode>& episodes,
                       const std::vector<std::vector<EpisodeOutcome>>& outcomes, int threads,
                       const std::filesystem::path& out) {
  struct Job {
    std::size_t model;
    std::size_t episode;
  };
  std::vector<Job> jobs;
  for (std::size_t m = 0; m < outcomes.size(); ++m) {
    for (std::size_t e = 0; e < episodes.size(); ++e) {
      if (outcomes[m][e].metrics.collision) jobs.push_back({m, e});
    }
  }
  std::vector<std::optional<CollisionAnalysis>> analyses(jobs.size());
  ProgressBar progress("collisions", static_cast<std::int64_t>(jobs.size()), "collisions");
  ThreadPool pool(threads + 1);  // the caller only shows progress
  std::atomic<int> done{0};
  pool.ParallelFor(
      static_cast<int>(jobs.size()),
      [&](int j) {
        analyses[j] = AnalyseCollision(episodes[jobs[j].episode].scenario,
                                       outcomes[jobs[j].model][jobs[j].episode].actions);
        ++done;
      },
      [&] { progress.Update(done); });
  progress.Finish();
  std::vector<CollisionCounts> counts(policies.size());
  std::string csv = CollisionCsvHeader();
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    const std::string& model = policies[jobs[j].model].name();
    if (!analyses[j]) {
      throw std::runtime_error(model + " on " + episodes[jobs[j].episode].name +
                               ": its recorded actions do not collide when replayed");
    }
    counts[jobs[j].model].collisions.push_back(*analyses[j]);
    csv += CollisionCsvRow(model, episodes[jobs[j].episode].name, *analyses[j]);
  }
  for (std::size_t m = 0; m < policies.size(); ++m) {
    counts[m].model = policies[m].name();
    counts[m].episodes = static_cast<int>(episodes.size());
  }
  WriteTextFileAtomically(out / "collisions.csv", csv);
  const std::string markdown = CollisionSummaryMarkdown(counts);
  WriteTextFileAtomically(out / "collisions.md", markdown);
  std::cout << "\n" << markdown;
}

// What an evaluation writes into its folder besides config.yaml and its log: a run with
// --overwrite removes them first, so no figure, replay or collision analysis of the earlier run
// stays beside the new summary.
const std::vector<std::string> kEvaluationOutputs = {
    "episodes.csv", "summary.json",   "summary.md",   "figures",
    "replays",      "collisions.csv", "collisions.md"};

int Evaluate(int argc, char** argv) {
  CLI::App app{
      "Runs trained policies (TorchScript policy.pt) with deterministic actions on the shared "
      "test\n"
      "scenarios (training worlds from a fixed list of seeds, test mode) or on scenario files, "
      "and\n"
      "writes OUT/episodes.csv, OUT/summary.json, OUT/summary.md (mean and 95 % CIs per model,\n"
      "paired differences between models) and trajectory figures in OUT/figures/. Each policy "
      "runs\n"
      "under the observation settings (env.closeness, env.scan_history*) recorded in its file,\n"
      "else in its sidecar <policy>.yaml, else (with a warning) under this evaluation's."};
  std::vector<std::string> policy_paths;
  std::vector<std::string> names;
  std::vector<std::string> scenario_files;
  std::string out;
  app.add_option("--policy", policy_paths, "policy file (TorchScript), repeatable")->required();
  app.add_option("--name", names, "model name of each --policy, in order (default: run folder)");
  auto* scenario_option = app.add_option("--scenario", scenario_files,
                                         "evaluate on these scenario files instead, repeatable");
  app.add_option("--out", out, "output folder")->required();
  bool overwrite = false;
  app.add_flag("--overwrite", overwrite, "replace the evaluation already in --out");
  ReplayChoice replay_choice;
  app.add_flag("--replay", replay_choice.enabled,
               "also write replay pages (OUT/replays/<scenario>.html, every model in each): every "
               "scenario file, or the test scenarios chosen by --replay-first and "
               "--replay-collisions");
  bool analyse_collisions = false;
  app.add_flag("--analyse-collisions", analyse_collisions,
               "also replay every collision, name the obstacle hit, and search 1,065 manoeuvres "
               "from the step it came within 150 m and from 10, 30 and 60 s before the contact: "
               "OUT/collisions.csv, OUT/collisions.md");
  std::string reuse;
  app.add_option("--reuse", reuse,
                 "take the test episodes of each model that an earlier evaluation in DIR (--out's "
                 "own folder too) ran under the same settings, on the same scenarios, from the "
                 "same policy file (its bytes and sidecar unchanged) instead of running them "
                 "again; the outputs are those of a full run. Needs --trajectories 0, without "
                 "--replay and --analyse-collisions, which need the runs themselves")
      ->type_name("DIR")
      ->excludes(scenario_option);
  AddNumberFlag(app, "--replay-first", replay_choice.first,
                "with --replay: the first this many test scenarios", 0, 100000);
  AddNumberFlag(app, "--replay-collisions", replay_choice.collided,
                "with --replay: also the first this many other test scenarios in which some "
                "model collided",
                0, 100000);
  const OptionsBinding<EvaluateOptions> binding = EvaluateBinding();
  ConfigFlags config_flags(app, binding.Schema());
  config_flags.AddFlag("--episodes", "eval.episodes")->excludes(scenario_option);
  config_flags.AddFlag("--seed", "eval.seed");
  config_flags.AddFlag("--threads", "eval.threads");
  config_flags.AddFlag("--trajectories", "eval.trajectory_scenarios");
  config_flags.AddFlag("--file-figures", "eval.scenario_file_figures");
  config_flags.AddFlag("--trajectory-starts", "eval.trajectory_starts");
  ParseCommandLine(app, argc, argv);
  const Config config = config_flags.Resolve();
  const EvaluateOptions options = binding.Read(config);
  if (!reuse.empty() &&
      (options.trajectory_scenarios > 0 || replay_choice.enabled || analyse_collisions)) {
    throw UserError(
        "--reuse takes episodes without their runs: give --trajectories 0, and neither --replay "
        "nor --analyse-collisions");
  }

  const auto start = std::chrono::steady_clock::now();
  const int threads = ThreadCountOrAllCores(options.threads);
  // The policies' matrices are small: the episodes run in parallel instead, and LibTorch's
  // OpenMP threads would only spin against the episode threads (30x slower on 2 busy cores).
  at::set_num_threads(1);
  // Every input is checked before the output folder is touched.
  std::vector<Policy> policies = LoadPolicies(policy_paths, names);
  const bool on_files = !scenario_files.empty();
  const std::uint64_t seed = options.seed;
  const std::vector<EvaluationEpisode> episodes =
      on_files ? ScenarioFileEpisodes({scenario_files.begin(), scenario_files.end()})
               : TestEpisodes(seed, options.episodes);
  std::vector<std::string> fingerprints;
  fingerprints.reserve(policies.size());
  for (const Policy& policy : policies) fingerprints.push_back(PolicyFingerprint(policy.path()));
  // Read before the folder is prepared: --reuse may name --out, whose files a rerun replaces.
  const ReusableEpisodes reusable =
      LookForReusableEpisodes(reuse, config, binding.Schema(), policies, fingerprints, episodes);
  const RunFolder folder = RunFolder::Create(out, "evaluate");
  folder.StartNewRun({"summary.json"}, kEvaluationOutputs, overwrite,
                     "replace it with --overwrite");
  InitLogging("evaluate", folder.LogPath(), false);
  LogReuse(reuse, reusable, policies.size());
  folder.WriteResolvedConfig(config);
  spdlog::info("evaluating {} model(s) on {} {}", policies.size(), episodes.size(),
               on_files ? "scenario files" : "test scenarios");
  const std::vector<std::string> settings = ObservationSettingsLines(policies, options.env);

  const auto outcomes = RunUnlessReusable(policies, episodes, reusable, options.env, threads);
  const double evaluation_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<std::string> model_names;
  std::vector<std::string> model_policies;
  for (const Policy& policy : policies) {
    model_names.push_back(policy.name());
    model_policies.push_back(policy.path().string());
  }
  EvaluationReport report = MakeEvaluationReport(
      on_files ? "files" : "test", on_files ? std::nullopt : std::optional<std::uint64_t>(seed),
      model_names, model_policies, MetricsOf(outcomes));
  for (std::size_t m = 0; m < policies.size(); ++m) {
    report.models[m].observation_settings = settings[m];
    report.models[m].policy_fingerprint = fingerprints[m];
  }
  report.evaluator_build_id = ProgramBuildId();
  WriteTextFileAtomically(folder.path() / "episodes.csv",
                          EpisodeTable(model_names, episodes, outcomes));
  WriteTextFileAtomically(folder.path() / "summary.json",
                          EvaluationReportJson(report).dump(2) + "\n");
  const std::string markdown = EvaluationReportMarkdown(report);
  WriteTextFileAtomically(folder.path() / "summary.md", markdown);
  std::cout << markdown;

  if (replay_choice.enabled) {
    WriteReplays(policies, episodes, ReplayedEpisodes(replay_choice, on_files, outcomes),
                 options.env, threads, folder.path());
  }
  if (analyse_collisions) {
    AnalyseCollisions(policies, episodes, outcomes, threads, folder.path());
  }
  if (on_files) {
    PlotScenarioFileRuns(policies, episodes, outcomes, options.scenario_file_figures,
                         folder.path());
  } else {
    PlotTestTrajectories(policies, episodes, outcomes, options, threads, folder.path());
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("evaluation_s: %.2f\nwall_s: %.2f\n", evaluation_s, wall_s);
  return 0;
}

}  // namespace
}  // namespace colav

int main(int argc, char** argv) {
  return colav::RunProgram("evaluate", argc, argv, colav::Evaluate);
}

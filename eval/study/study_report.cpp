#include "eval/study/study_report.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "eval/study/goal_shortfall.h"
#include "eval/study/job_graph.h"
#include "eval/study/run_diagnostics.h"
#include "eval/study/study_figures.h"
#include "src/atomic_file.h"
#include "src/rate_interval.h"
#include "src/statistics.h"
#include "src/yaml_file.h"

namespace colav {
namespace {

constexpr std::uint64_t kBootstrapSeed = 0;  // fixed: the same results give the same report

std::vector<double> Pooled(const std::vector<const ModelEpisodes*>& seeds,
                           const std::string& metric) {
  std::vector<double> all;
  for (const ModelEpisodes* seed : seeds) {
    const std::vector<double>& values = seed->at(metric);
    all.insert(all.end(), values.begin(), values.end());
  }
  return all;
}

// Over seeds when there are several (the spread that matters between recipes), otherwise over
// the scenarios of the one model; intervals of bounded metrics stay in range.
MetricEstimate Estimate(const std::vector<const ModelEpisodes*>& seeds, const StudyMetric& metric) {
  const std::vector<double> pooled = Pooled(seeds, metric.name);
  const bool over_seeds = seeds.size() >= 2;
  std::vector<double> values = pooled;
  if (over_seeds) {
    values.clear();
    for (const ModelEpisodes* seed : seeds) values.push_back(Mean(seed->at(metric.name)));
  }
  MetricEstimate estimate{Mean(values), {}, "", InterquartileMean(pooled)};
  if (metric.is_rate && !over_seeds) {
    const auto successes = static_cast<std::int64_t>(
        std::llround(estimate.mean / metric.scale * static_cast<double>(pooled.size())));
    const Interval rate = WilsonInterval(successes, static_cast<std::int64_t>(pooled.size()));
    estimate.ci = {rate.low * metric.scale, rate.high * metric.scale};
    estimate.method = "Wilson";
  } else if (metric.bounded()) {
    estimate.ci = PercentileBootstrapMean(values, kBootstrapSeed);
    estimate.method = "bootstrap";
  } else {
    const MeanConfidenceInterval summary = Summarise(values);
    estimate.ci = {summary.low, summary.high};
    estimate.method = "t";
  }
  if (over_seeds) estimate.method += " over seeds";
  return estimate;
}

// scores[seed][scenario], higher is better.
SeedScores Scores(const std::vector<const ModelEpisodes*>& seeds, const StudyMetric& metric) {
  SeedScores scores;
  for (const ModelEpisodes* seed : seeds) {
    scores.push_back(seed->at(metric.name));
    if (!metric.higher_is_better) {
      for (double& value : scores.back()) value = -value;
    }
  }
  return scores;
}

// The models of the set as (name, seeds): configurations and ensemble kinds gather their seed
// models.
std::vector<std::pair<std::string, std::vector<const ModelEpisodes*>>> Groups(
    const StudySpec& spec, const ScenarioSetResults& results) {
  std::vector<std::pair<std::string, std::vector<const ModelEpisodes*>>> groups;
  for (const SeededModel& model : spec.SeededModels()) {
    std::vector<const ModelEpisodes*> seeds;
    seeds.reserve(static_cast<std::size_t>(model.seeds));
    for (int k = 0; k < model.seeds; ++k) {
      seeds.push_back(&results.models.at(SeedModelName(model.name, k)));
    }
    groups.emplace_back(model.name, seeds);
  }
  for (const auto& [name, episodes] : results.models) {
    if (name.rfind("ref.", 0) == 0) groups.push_back({name, {&episodes}});
  }
  return groups;
}

std::string Cell(const MetricEstimate& estimate) {
  return fmt::format("{:.1f} [{:.1f}, {:.1f}]", estimate.mean, estimate.ci.low, estimate.ci.high);
}

std::string Cell(const ImprovementEstimate& estimate) {
  return fmt::format("{:.2f} [{:.2f}, {:.2f}]", estimate.probability, estimate.ci.low,
                     estimate.ci.high);
}

nlohmann::json ToJson(const OutcomeBreakdown& outcomes) {
  nlohmann::json json = {{"time_out_scenarios", outcomes.time_out_scenarios},
                         {"time_out_every_seed", outcomes.time_out_every_seed}};
  for (const auto& [name, part] : {std::pair{"collision", outcomes.collision},
                                   {"time_out", outcomes.time_out},
                                   {"rest", outcomes.rest}}) {
    json[name] = {{"share", part.share},
                  {"progress_lost", part.progress_lost},
                  {"cross_track_error", part.cross_track_error}};
  }
  return json;
}

nlohmann::json ToJson(const ScenarioSetReport& report) {
  nlohmann::json json = {{"episodes", report.episodes}};
  for (const ModelSummary& model : report.models) {
    nlohmann::json metrics;
    for (const auto& [name, e] : model.metrics) {
      metrics[name] = {{"mean", e.mean},
                       {"low", e.ci.low},
                       {"high", e.ci.high},
                       {"interval", e.method},
                       {"iqm", e.iqm}};
    }
    json["models"].push_back({{"name", model.name},
                              {"seeds", model.seeds},
                              {"metrics", metrics},
                              {"outcomes", ToJson(model.outcomes)}});
  }
  json["probability_of_improvement"] = nlohmann::json::array();
  for (const ImprovementSummary& row : report.improvements) {
    nlohmann::json metrics;
    for (const auto& [name, e] : row.metrics) {
      metrics[name] = {{"probability", e.probability}, {"low", e.ci.low}, {"high", e.ci.high}};
    }
    const ProgressAtGoalSplit& split = row.progress_split;
    json["probability_of_improvement"].push_back(
        {{"model", row.model},
         {"over", row.over},
         {"metrics", metrics},
         {"progress_split",
          {{"both_at_goal_share", split.both_at_goal_share},
           {"both_at_goal_probability", split.both_at_goal_probability},
           {"elsewhere_probability", split.elsewhere_probability}}}});
  }
  json["ensemble_gains"] = nlohmann::json::array();
  for (const EnsembleGain& gain : report.ensemble_gains) {
    nlohmann::json metrics;
    for (const auto& [name, difference] : gain.metrics) {
      metrics[name] = ConfidenceIntervalJson(difference);
    }
    json["ensemble_gains"].push_back({{"ensemble", gain.ensemble}, {"metrics", metrics}});
  }
  json["agents_among_seeds"] = nlohmann::json::array();
  for (const AgentAmongSeeds& row : report.agents_among_seeds) {
    nlohmann::json metrics;
    for (const auto& [name, place] : row.metrics) {
      metrics[name] = {{"value", place.value},
                       {"prediction_low", place.prediction.low},
                       {"prediction_high", place.prediction.high},
                       {"inside", place.inside},
                       {"seeds_better", place.seeds_better},
                       {"seeds_worse", place.seeds_worse},
                       {"seeds", place.seeds},
                       {"rank_p", place.rank_p}};
    }
    json["agents_among_seeds"].push_back(
        {{"config", row.config}, {"agent", row.agent}, {"metrics", metrics}});
  }
  return json;
}

void ModelTable(std::ostringstream& md, const ScenarioSetReport& report) {
  md << "| model | seeds |";
  for (const StudyMetric& metric : StudyMetrics()) md << ' ' << metric.label << " |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < StudyMetrics().size(); ++i) md << "---|";
  md << '\n';
  for (const ModelSummary& model : report.models) {
    md << "| " << model.name << " | " << model.seeds << " |";
    for (const StudyMetric& metric : StudyMetrics()) {
      md << ' ' << Cell(model.metrics.at(metric.name)) << " |";
    }
    md << '\n';
  }
  md << "\nIntervals: 95 %. Configurations with several seeds: over the training seeds' means "
        "(ensemble kinds: over their ensembles' means), percentile bootstrap for progress and "
        "rates, Student-t otherwise. Single agents: over the scenarios, Wilson score for rates, "
        "percentile bootstrap for progress, Student-t otherwise.\n";
}

// "+1.4 [0.8, 2.0]", bold when the interval excludes 0; the difference alone for one ensemble.
std::string Cell(const MeanConfidenceInterval& difference) {
  if (difference.count < 2) return fmt::format("{:+.2f}", difference.mean);
  const std::string cell =
      fmt::format("{:+.2f} [{:.2f}, {:.2f}]", difference.mean, difference.low, difference.high);
  return difference.low > 0.0 || difference.high < 0.0 ? "**" + cell + "**" : cell;
}

std::string Cell(const SeedPlacement& place) {
  return fmt::format("{:.1f} {} [{:.1f}, {:.1f}], {} of {} better, rank p {:.2f}", place.value,
                     place.inside ? "in" : "**out of**", place.prediction.low,
                     place.prediction.high, place.seeds_better, place.seeds, place.rank_p);
}

// " | a | b" for the metrics `names` of `metrics`, each through its Cell.
template <typename Estimate>
std::string MetricCells(const std::map<std::string, Estimate>& metrics,
                        std::initializer_list<const char*> names) {
  std::string cells;
  for (const char* name : names) cells += " | " + Cell(metrics.at(name));
  return cells;
}

void ImprovementTable(std::ostringstream& md, const ScenarioSetReport& report) {
  if (report.improvements.empty()) return;
  md << "\nProbability of improvement: P(model better than the other on a random scenario and "
        "training seed; ties count half), with a 95 % bootstrap interval over seeds and "
        "scenarios. Above 0.5 with the whole interval: better. The progress comparison split: "
        "P(more progress) where both reached the goal (and the share of such pairs), where "
        "either did not. Where both reached the goal, the one that entered the goal's 5 m "
        "circle farther beside the path ends nearer the path's end and wins. Progress to the "
        "finish counts every goal as 100 %, so only the episodes that end short of it "
        "decide.\n\n"
        "| model | over | progress | cte | collisions | return | progress: both at goal (share) "
        "/ elsewhere | progress to the finish |\n|---|---|---|---|---|---|---|---|\n";
  for (const ImprovementSummary& row : report.improvements) {
    const ProgressAtGoalSplit& split = row.progress_split;
    md << "| " << row.model << " | " << row.over
       << MetricCells(row.metrics, {"progress", "cross_track_error", "collision", "return"})
       << fmt::format(" | {:.2f} ({:.0f} %) / {:.2f}", split.both_at_goal_probability,
                      100.0 * split.both_at_goal_share, split.elsewhere_probability)
       << MetricCells(row.metrics, {kProgressToFinish}) << " |\n";
  }
}

void EnsembleGainTable(std::ostringstream& md, const ScenarioSetReport& report) {
  if (report.ensemble_gains.empty()) return;
  md << "\nWhat combining changes: each ensemble's mean minus the mean of its own members' means "
        "(points for % metrics), on the same scenarios; over a kind's ensembles, the mean with a "
        "95 % Student-t interval (bold: it excludes 0).\n\n"
        "| ensemble | progress | cte m | collisions | time-outs | return |\n"
        "|---|---|---|---|---|---|\n";
  for (const EnsembleGain& gain : report.ensemble_gains) {
    md << "| " << gain.ensemble
       << MetricCells(gain.metrics,
                      {"progress", "cross_track_error", "collision", "time_out", "return"})
       << " |\n";
  }
}

void AgentsAmongSeedsTable(std::ostringstream& md, const ScenarioSetReport& report) {
  if (report.agents_among_seeds.empty()) return;
  md << "\nCould each single agent have been one more training seed of a configuration? Its "
        "mean, the configuration's 95 % prediction interval for one more seed's mean (Student-t "
        "over the seeds' means, assuming they spread normally: mean +- t sd sqrt(1 + 1/n)), and "
        "how many of the seeds did better than the agent, with a rank test that assumes no "
        "shape of the spread (rank p: twice the chance that one more seed of ours would rank at "
        "least as far out among the n + 1, ties counted against the test; it cannot fall below "
        "2 / (n + 1), so 0.05 needs 39 seeds). A single agent is one seed of its own "
        "recipe, so its interval over the scenarios does not hold another seed of that "
        "recipe.\n\n"
        "| configuration | agent | progress % | cte m | collisions % |\n|---|---|---|---|---|\n";
  for (const AgentAmongSeeds& row : report.agents_among_seeds) {
    md << "| " << row.config << " | " << row.agent
       << MetricCells(row.metrics, {"progress", "cross_track_error", "collision"}) << " |\n";
  }
}

std::string Cell(const OutcomePart& part) {
  return fmt::format("{:.2f} ({:.1f} %)", part.progress_lost, part.share);
}

void OutcomeTable(std::ostringstream& md, const ScenarioSetReport& report) {
  md << "\nWhere the progress and the cross-track error go: the points of mean progress lost and "
        "the metres of mean cross-track error from the episodes that collided, timed out, or "
        "ended otherwise (at the goal, which the goal test declares within 5 m of the end or at "
        "99 % of the path: about a point lost even without a failure), each with its share of the "
        "episodes; and the scenarios with a time-out, of which those where every seed timed "
        "out.\n\n"
        "| model | progress lost: collisions | time-outs | the rest | cte m: collisions | "
        "time-outs | the rest | time-out scenarios (every seed) |\n"
        "|---|---|---|---|---|---|---|---|\n";
  for (const ModelSummary& model : report.models) {
    const OutcomeBreakdown& o = model.outcomes;
    md << fmt::format("| {} | {} | {} | {} | {:.1f} | {:.1f} | {:.1f} | {} ({}) |\n", model.name,
                      Cell(o.collision), Cell(o.time_out), Cell(o.rest),
                      o.collision.cross_track_error, o.time_out.cross_track_error,
                      o.rest.cross_track_error, o.time_out_scenarios, o.time_out_every_seed);
  }
}

// The paper's numbers beside ours, for the configurations the paper reports.
void PaperTable(std::ostringstream& md, const ScenarioSetReport& report,
                const std::filesystem::path& paper_results) {
  if (paper_results.empty()) return;
  const YAML::Node paper = LoadYamlFile(paper_results)["models"];
  md << "\nThe paper's table beside ours (ours / paper):\n\n| model |";
  for (const char* metric : {"progress", "cross_track_error", "duration", "collision"}) {
    md << ' ' << metric << " |";
  }
  md << "\n|---|---|---|---|---|\n";
  for (const ModelSummary& model : report.models) {
    if (!paper[model.name]) continue;
    md << "| " << model.name << " |";
    for (const char* metric : {"progress", "cross_track_error", "duration", "collision"}) {
      const YAML::Node theirs = paper[model.name][metric];
      md << ' ' << Cell(model.metrics.at(metric)) << " / " << theirs["mean"].as<double>() << " ["
         << theirs["low"].as<double>() << ", " << theirs["high"].as<double>() << "] |";
    }
    md << '\n';
  }
}

// The set's figures, drawn into OUT/figures/ and linked from the report.
void Figures(std::ostringstream& md, const StudySpec& spec, const std::filesystem::path& out,
             const std::string& set, const ScenarioSetResults& results,
             const ScenarioSetReport& report) {
  const std::string models = "figures/" + set + "_models.png";
  DrawModelsFigure(spec, results, report,
                   fmt::format("{}: {} scenarios (master seed {}), mean and 95 % CI", spec.name,
                               report.episodes, results.seed),
                   out / models);
  md << "\n![every model on these scenarios](" << models << ")\n";
  const std::string trade_off = "figures/" + set + "_trade_off.png";
  DrawTradeOffFigure(
      spec, report,
      fmt::format("{}: collisions against progress and cross-track error, mean and 95 % CI",
                  spec.name),
      out / trade_off);
  md << "\n![collisions against progress and cross-track error](" << trade_off << ")\n";
  const auto sweep = BetaSweep(spec);
  if (set != "study" || sweep.empty()) return;
  const std::string beta = "figures/beta_sweep.png";
  DrawBetaSweepFigure(results, report, sweep, out / beta);
  md << "\n![the beta sweep](" << beta << ")\n";
}

// How the runs of each configuration and kind of fine-tune ended (run_diagnostics.h), seed by
// seed: into the report's table and summary.json's "runs".
void RunsTable(std::ostringstream& md, nlohmann::json& json, const StudySpec& spec,
               const std::filesystem::path& out) {
  md << "\nHow the runs ended, seed by seed: wall-clock, the action distribution's standard "
        "deviation at the last update (far past 1, the clipped actions steer bang-bang), and the "
        "training episodes' collisions and time-outs over the last tenth of the steps (sampled "
        "actions, training worlds).\n\n"
        "| PPO runs of | wall-clock s | std at the end | training collisions % | training "
        "time-outs % |\n|---|---|---|---|---|\n";
  for (const PpoRunKind& kind : PpoRunKinds(spec)) {
    std::vector<std::string> walls, stds, collisions, time_outs;
    for (const std::filesystem::path& folder : kind.folders) {
      const RunDiagnostics run = ReadRunDiagnostics(out / folder);
      walls.push_back(fmt::format("{:.0f}", run.wall_s));
      stds.push_back(fmt::format("{:.3g}", run.final_std));
      collisions.push_back(fmt::format("{:.1f}", run.late_collisions));
      time_outs.push_back(fmt::format("{:.1f}", run.late_time_outs));
      json["runs"][kind.name].push_back({{"wall_s", run.wall_s},
                                         {"final_std", run.final_std},
                                         {"late_episodes", run.late_episodes},
                                         {"late_collisions", run.late_collisions},
                                         {"late_time_outs", run.late_time_outs}});
    }
    md << fmt::format("| {} | {} | {} | {} | {} |\n", kind.name, fmt::join(walls, ", "),
                      fmt::join(stds, ", "), fmt::join(collisions, ", "),
                      fmt::join(time_outs, ", "));
  }
}

// The VAE figures, when the study's figure jobs drew them (job_graph.h).
void VaeFigures(std::ostringstream& md, const std::filesystem::path& out) {
  const std::filesystem::path vae = VaeFiguresFolder();
  if (std::filesystem::exists(out / vae / "latent_kde.png")) {
    md << "\n## The VAE figures\n\n![decoder padding](" << (vae / "padding_comparison.png").string()
       << ")\n\n![latent densities](" << (vae / "latent_kde.png").string() << ")\n";
  }
}

// How the runs ended, and the training curves of each kind of run its figure job drew.
void TrainingSection(std::ostringstream& md, nlohmann::json& json, const StudySpec& spec,
                     const std::filesystem::path& out) {
  md << "\n## Training\n";
  RunsTable(md, json, spec, out);
  for (const PpoRunKind& kind : PpoRunKinds(spec)) {
    const std::filesystem::path png = TrainingFigurePath(kind.name);
    if (std::filesystem::exists(out / png)) {
      md << "\n![training of " << kind.name << "](" << png.string() << ")\n";
    }
  }
}

// The ensemble kinds and the runs they average, into the report's head and summary.json.
void EnsembleSection(std::ostringstream& md, nlohmann::json& json, const StudySpec& spec) {
  if (spec.ensembles.empty()) return;
  md << "\nEnsembles, each acting with the mean of its members' deterministic actions (unless "
        "said otherwise); ensemble k "
        "of a kind of count n takes seed k + j n of a configuration listed for the j-th time "
        "(j = 0, 1, ...), so the n ensembles share no run:\n\n";
  for (const EnsembleSpec& ensemble : spec.ensembles) {
    md << fmt::format("- {}: {} of [{}]{}\n", ensemble.name, ensemble.count,
                      fmt::join(ensemble.members, ", "), DescribeEnsembleRule(ensemble));
    json["ensembles"][ensemble.name] = {{"members", ensemble.members}, {"count", ensemble.count}};
    if (ensemble.near_within_m) {
      json["ensembles"][ensemble.name]["near_within_m"] = *ensemble.near_within_m;
    }
    if (ensemble.stall) {
      json["ensembles"][ensemble.name]["stall_pace_mps"] = ensemble.stall->pace_mps;
      json["ensembles"][ensemble.name]["stall_steps"] = ensemble.stall->steps;
    }
  }
}

// The seconds each student of `student` took to distil (its STUDENT.pt.json), NaN when unread.
std::vector<double> DistillationSeconds(const StudentSpec& student,
                                        const std::filesystem::path& out) {
  std::vector<double> seconds;
  for (int k = 0; k < student.count; ++k) {
    std::ifstream in(out / StudentSummaryFile(student.name, k));
    const nlohmann::json summary = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    seconds.push_back(summary.is_object() ? summary.value("seconds", NAN) : NAN);
  }
  return seconds;
}

// The kinds of student, what each imitates and starts from, into the report's head and
// summary.json.
void StudentSection(std::ostringstream& md, nlohmann::json& json, const StudySpec& spec,
                    const std::filesystem::path& out) {
  if (spec.students.empty()) return;
  md << "\nStudents, each one recurrent network distilled by DAgger (distill_policy) from the "
        "teacher's seed k, starting from a run of a recurrent configuration (the one the "
        "teacher's ensemble k takes, if it is a member; else seed k):\n\n";
  for (const StudentSpec& student : spec.students) {
    const std::vector<double> seconds = DistillationSeconds(student, out);
    md << fmt::format(
        "- {}: {} of {} starting from {}{}; seconds of each distillation: {:.0f}\n", student.name,
        student.count, student.teacher, student.start,
        student.options.empty() ? "" : fmt::format(", with {}", fmt::join(student.options, " ")),
        fmt::join(seconds, ", "));
    json["students"][student.name] = {{"teacher", student.teacher},
                                      {"start", student.start},
                                      {"options", student.options},
                                      {"count", student.count},
                                      {"seconds", seconds}};
  }
}

// The kinds of fine-tuned student, what each starts from and what it changes, into the report's
// head and summary.json.
void FineTuneSection(std::ostringstream& md, nlohmann::json& json, const StudySpec& spec) {
  if (spec.fine_tunes.empty()) return;
  md << "\nFine-tuned students, each student k trained further by PPO (train_ppo from its policy, "
        "policy.init) with the settings of the run it started from, then the kind's own:\n\n";
  for (const FineTuneSpec& fine_tune : spec.fine_tunes) {
    const StudentSpec& student = *spec.FindStudent(fine_tune.student);
    const std::int64_t steps = spec.StepsOf(fine_tune);
    md << fmt::format("- {}: {} of {}, {} steps with the settings of {}{}\n", fine_tune.name,
                      fine_tune.count, student.name, steps, student.start,
                      fine_tune.overrides.empty()
                          ? ""
                          : fmt::format(" and {}", fmt::join(fine_tune.overrides, ", ")));
    json["fine_tunes"][fine_tune.name] = {{"student", student.name},
                                          {"start", student.start},
                                          {"steps", steps},
                                          {"set", fine_tune.overrides},
                                          {"count", fine_tune.count}};
  }
}

// The metrics the goal bounds, in the report's order.
std::vector<StudyMetric> GoalMetrics(const StudySpec& spec) {
  std::vector<StudyMetric> bounded;
  for (const StudyMetric& metric : StudyMetrics()) {
    if (spec.evaluation.goal.count(metric.name) > 0) bounded.push_back(metric);
  }
  return bounded;
}

// "progress % at least 97, cte m at most 17, collisions % at most 3"
std::string DescribeGoal(const StudySpec& spec) {
  std::vector<std::string> bounds;
  for (const StudyMetric& metric : GoalMetrics(spec)) {
    bounds.push_back(fmt::format("{} {} {}", metric.label,
                                 metric.higher_is_better ? "at least" : "at most",
                                 spec.evaluation.goal.at(metric.name)));
  }
  return fmt::format("{}", fmt::join(bounds, ", "));
}

// The heading of a goal table: the `leads` columns, the networks, each bound's metric, the sum.
void GoalHeading(std::ostringstream& md, const StudySpec& spec,
                 const std::vector<std::string>& leads) {
  md << "| " << fmt::format("{}", fmt::join(leads, " | ")) << " | networks |";
  for (const StudyMetric& metric : GoalMetrics(spec)) md << ' ' << metric.label << " |";
  md << " shortfall |\n|";
  for (std::size_t i = 0; i < leads.size() + spec.evaluation.goal.size() + 2; ++i) md << "---|";
  md << '\n';
}

// One model's row: its mean per bound, with how far it falls short of the bound where it does
// (short of an at-least bound, over an at-most one), and the sum.
void GoalRow(std::ostringstream& md, const StudySpec& spec, const std::string& lead,
             const GoalShortfall& shortfall, const ModelSummary& summary) {
  md << "| " << lead << " | " << shortfall.networks << " |";
  for (const StudyMetric& metric : GoalMetrics(spec)) {
    const double mean = summary.metrics.at(metric.name).mean;
    const double short_by = shortfall.by_metric.at(metric.name);
    md << (short_by > 0.0 ? fmt::format(" {:.2f} ({:.2f} {}) |", mean, short_by,
                                        metric.higher_is_better ? "short" : "over")
                          : fmt::format(" {:.2f} |", mean));
  }
  md << (shortfall.met() ? std::string(" **0** |") : fmt::format(" {:.2f} |", shortfall.total))
     << '\n';
}

nlohmann::json ToJson(const GoalShortfall& shortfall) {
  return {{"model", shortfall.model},
          {"networks", shortfall.networks},
          {"metrics", shortfall.by_metric},
          {"total", shortfall.total}};
}

// Every model of the study against the goal, on one scenario set.
void GoalTable(std::ostringstream& md, nlohmann::json& json, const StudySpec& spec,
               const ScenarioSetReport& report, const std::vector<GoalShortfall>& shortfalls) {
  md << "\nAgainst the goal (" << DescribeGoal(spec)
     << "): each model's means, how far each falls short of its bound, and the sum of those (the "
        "shortfall, in the report's units; 0: every bound met).\n\n";
  GoalHeading(md, spec, {"model"});
  json["goal_shortfall"] = nlohmann::json::array();
  for (const GoalShortfall& shortfall : shortfalls) {
    GoalRow(md, spec, shortfall.model, shortfall, SummaryOf(report, shortfall.model));
    json["goal_shortfall"].push_back(ToJson(shortfall));
  }
}

// The model the validation scenarios choose by the goal, and its figures on the test's;
// `shortfalls` by scenario set (none without a goal).
void ChosenOnValidation(std::ostringstream& md, nlohmann::json& json, const StudySpec& spec,
                        const std::map<std::string, ScenarioSetReport>& reports,
                        const std::map<std::string, std::vector<GoalShortfall>>& shortfalls) {
  if (shortfalls.count("validation") == 0) return;
  const ScenarioSetReport& validation = reports.at("validation");
  const ScenarioSetReport& test = reports.at("study");
  const GoalShortfall& chosen = ChooseByShortfall(shortfalls.at("validation"));
  const std::vector<GoalShortfall>& on_test = shortfalls.at("study");
  const GoalShortfall& chosen_on_test =
      *std::find_if(on_test.begin(), on_test.end(),
                    [&](const GoalShortfall& s) { return s.model == chosen.model; });
  md << "\n## Chosen on the validation scenarios\n\nThe goal: " << DescribeGoal(spec)
     << ". Of the study's models, the one whose means on the validation scenarios fall least "
        "short of it (the sum of each mean's shortfall from its bound, in the report's units; ties "
        "to fewer networks, then to the first in the study file). Only its figures on the test "
        "scenarios are a claim.\n\n";
  GoalHeading(md, spec, {"scenarios", "model"});
  GoalRow(md, spec, "validation | " + chosen.model, chosen, SummaryOf(validation, chosen.model));
  GoalRow(md, spec, "test | " + chosen.model, chosen_on_test, SummaryOf(test, chosen.model));
  md << "\n**" << chosen.model
     << (chosen_on_test.met() ? std::string(" meets the goal on the test scenarios.**\n")
                              : fmt::format(" misses the goal on the test scenarios by {:.2f}.**\n",
                                            chosen_on_test.total));
  json["chosen_on_validation"] = {{"model", chosen.model},
                                  {"networks", chosen.networks},
                                  {"validation_shortfall", chosen.total},
                                  {"test_shortfall", chosen_on_test.total},
                                  {"meets_goal_on_test", chosen_on_test.met()}};
}

// The heading of a scenario set's section.
std::string ScenarioSetTitle(const std::string& set) {
  if (set == "paper") return "The paper's test";
  if (set == "validation") return "Validation, to choose on (not the test)";
  return "Test";
}

}  // namespace

const ModelSummary& SummaryOf(const ScenarioSetReport& report, const std::string& model) {
  return *std::find_if(report.models.begin(), report.models.end(),
                       [&](const ModelSummary& summary) { return summary.name == model; });
}

std::string DescribeEnsembleRule(const EnsembleSpec& ensemble) {
  std::string stall;
  if (ensemble.stall) {
    // With more than one relief the second keeps the helm only until the next stall.
    const bool one_relief = ensemble.members.size() == 2;
    stall = fmt::format(
        "{} the vessel's pace towards the look-ahead point, averaged over {} steps, falls "
        "below {} m/s{}",
        one_relief ? "for the rest of the episode once" : "from the step", ensemble.stall->steps,
        ensemble.stall->pace_mps,
        one_relief ? ""
                   : ", each later member from the next stall on, the last to the episode's "
                     "end (the average restarts at each stall)");
  }
  if (ensemble.near_within_m) {
    return fmt::format(", the first steering within {} m of an obstacle, the second otherwise{}",
                       *ensemble.near_within_m, stall.empty() ? "" : " and " + stall);
  }
  return stall.empty() ? "" : ", the first steering, the second " + stall;
}

ScenarioSetReport SummariseScenarioSet(const StudySpec& spec, const ScenarioSetResults& results,
                                       const std::string& reference_config) {
  ScenarioSetReport report;
  report.episodes = results.episodes;
  const auto groups = Groups(spec, results);
  for (const auto& [name, seeds] : groups) {
    ModelSummary summary{name, static_cast<int>(seeds.size()), {}, BreakDownOutcomes(seeds)};
    for (const StudyMetric& metric : StudyMetrics()) {
      summary.metrics[metric.name] = Estimate(seeds, metric);
    }
    report.models.push_back(summary);
  }
  for (const SeededModel& model : spec.SeededModels()) {
    const auto& seeds = *std::find_if(groups.begin(), groups.end(),
                                      [&](const auto& g) { return g.first == model.name; });
    const std::string& compared_with =
        model.compare_to.empty() ? reference_config : model.compare_to;
    const auto reference = std::find_if(groups.begin(), groups.end(),
                                        [&](const auto& g) { return g.first == compared_with; });
    for (const auto& other : groups) {
      const bool is_reference = reference != groups.end() && other.first == reference->first;
      if (other.first == model.name || !(is_reference || other.first.rfind("ref.", 0) == 0)) {
        continue;
      }
      ImprovementSummary row{
          model.name, other.first, {}, SplitProgressAtGoal(seeds.second, other.second)};
      for (const StudyMetric& metric : StudyMetrics()) {
        row.metrics[metric.name] = ProbabilityOfImprovementInterval(
            Scores(seeds.second, metric), Scores(other.second, metric), kBootstrapSeed);
      }
      row.metrics[kProgressToFinish] = ProbabilityOfImprovementInterval(
          ProgressToFinish(seeds.second), ProgressToFinish(other.second), kBootstrapSeed);
      report.improvements.push_back(row);
      if (other.second.size() == 1 && seeds.second.size() >= 2) {
        report.agents_among_seeds.push_back(
            PlaceAmongSeeds(model.name, seeds.second, other.first, *other.second.front()));
      }
    }
  }
  for (const EnsembleSpec& ensemble : spec.ensembles) {
    report.ensemble_gains.push_back(MeasureEnsembleGain(ensemble, results));
  }
  return report;
}

void WriteStudyReport(const StudySpec& spec, const std::filesystem::path& out, double wall_s) {
  const std::map<std::string, ScenarioSetResults> sets = ReadStudyResults(spec, out);
  nlohmann::json json = {{"study", spec.name},
                         {"seeds", spec.ppo_seeds},
                         {"ppo_steps", spec.ppo_steps},
                         {"wall_s", wall_s}};
  std::vector<std::string> own_steps;  // configurations trained longer or shorter than the study
  for (const PpoConfigSpec& config : spec.ppo_configs) {
    const std::int64_t steps = spec.StepsOf(config);
    json["config_steps"][config.name] = steps;
    if (steps != spec.ppo_steps) own_steps.push_back(fmt::format("{}: {}", config.name, steps));
  }
  std::ostringstream md;
  md << "# Study " << spec.name << "\n\n"
     << spec.ppo_configs.size() << " PPO configuration(s) x " << spec.ppo_seeds
     << " training seed(s) of " << spec.ppo_steps << " steps"
     << (own_steps.empty() ? "" : fmt::format(" ({})", fmt::join(own_steps, ", ")))
     << "; wall-clock of the study (every run of it) " << fmt::format("{:.0f}", wall_s) << " s.\n";
  EnsembleSection(md, json, spec);
  StudentSection(md, json, spec, out);
  FineTuneSection(md, json, spec);
  std::map<std::string, ScenarioSetReport> reports;
  std::map<std::string, std::vector<GoalShortfall>> shortfalls;  // none without a goal
  for (const auto& [set, results] : sets) {
    reports[set] = SummariseScenarioSet(spec, results, spec.evaluation.compare_to);
    if (!spec.evaluation.goal.empty()) {
      shortfalls[set] = MeasureGoalShortfalls(spec, reports.at(set));
    }
  }
  if (!spec.evaluation.goal.empty()) json["goal"] = spec.evaluation.goal;
  ChosenOnValidation(md, json, spec, reports, shortfalls);
  for (const auto& [set, results] : sets) {
    const ScenarioSetReport& report = reports.at(set);
    json["scenario_sets"][set] = ToJson(report);
    json["scenario_sets"][set]["seed"] = results.seed;
    md << "\n## " << ScenarioSetTitle(set) << ": " << report.episodes << " scenarios (master seed "
       << results.seed << ")\n\n";
    ModelTable(md, report);
    if (!shortfalls.empty()) {
      GoalTable(md, json["scenario_sets"][set], spec, report, shortfalls.at(set));
    }
    Figures(md, spec, out, set, results, report);
    ImprovementTable(md, report);
    EnsembleGainTable(md, report);
    AgentsAmongSeedsTable(md, report);
    OutcomeTable(md, report);
    if (set == "paper") PaperTable(md, report, spec.evaluation.paper_results);
  }
  VaeFigures(md, out);
  TrainingSection(md, json, spec, out);
  WriteTextFileAtomically(out / "summary.json", json.dump(2) + "\n");
  WriteTextFileAtomically(out / "REPORT.md", md.str());
}

}  // namespace colav

#include "eval/study/study_report.h"

#include <gtest/gtest.h>

#include <cmath>

namespace colav {
namespace {

// One model's episodes: every metric's value per scenario (progress and rates in %); an episode
// with less than 90 % progress and no collision timed out; its return is progress - collision.
ModelEpisodes Episodes(std::vector<double> progress, std::vector<double> cte,
                       std::vector<double> collision) {
  const std::vector<double> constant(progress.size(), 500.0);
  std::vector<double> time_out(progress.size(), 0.0);
  std::vector<double> episode_return(progress.size(), 0.0);
  for (std::size_t i = 0; i < progress.size(); ++i) {
    time_out[i] = progress[i] < 90.0 && collision[i] == 0.0 ? 100.0 : 0.0;
    episode_return[i] = progress[i] - collision[i];
  }
  return {{"progress", progress},
          {"cross_track_error", cte},
          {"duration", constant},
          {"collision", collision},
          {"goal", std::vector<double>(progress.size(), 0.0)},
          {"time_out", time_out},
          {"return", episode_return}};
}

// A study of one configuration, "mine", of `seeds` training seeds.
StudySpec OneConfiguration(int seeds) {
  StudySpec spec;
  spec.ppo_seeds = seeds;
  spec.ppo_configs = {{"mine", "baseline", "", true, {}}};
  return spec;
}

TEST(StudyReportTest, SummariesOverSeedsAndScenariosAndImprovement) {
  StudySpec spec;
  spec.ppo_seeds = 2;
  spec.ppo_configs = {{"better", "baseline", "", true, {}}, {"baseline", "baseline", "", true, {}}};
  ScenarioSetResults results;
  results.episodes = 4;
  results.models["better.seed_0"] = Episodes({100, 100, 100, 100}, {10, 10, 10, 10}, {0, 0, 0, 0});
  results.models["better.seed_1"] = Episodes({90, 90, 90, 90}, {20, 20, 20, 20}, {0, 0, 0, 100});
  results.models["baseline.seed_0"] = Episodes({80, 80, 80, 80}, {30, 30, 30, 30}, {100, 0, 0, 0});
  results.models["baseline.seed_1"] =
      Episodes({70, 70, 70, 70}, {40, 40, 40, 40}, {100, 100, 0, 0});
  results.models["ref.agent"] = Episodes({100, 50, 100, 50}, {15, 15, 15, 15}, {0, 100, 0, 0});

  const ScenarioSetReport report = SummariseScenarioSet(spec, results, "baseline");
  ASSERT_EQ(report.models.size(), 3U);
  const ModelSummary& better = report.models[0];
  EXPECT_EQ(better.name, "better");
  EXPECT_EQ(better.seeds, 2);
  const MetricEstimate& progress = better.metrics.at("progress");
  EXPECT_DOUBLE_EQ(progress.mean, 95.0);
  // Bounded: a bootstrap over the seed means 100 and 90 stays within them.
  EXPECT_EQ(progress.method, "bootstrap over seeds");
  EXPECT_GE(progress.ci.low, 90.0);
  EXPECT_LE(progress.ci.high, 100.0);
  EXPECT_DOUBLE_EQ(better.metrics.at("collision").mean, 12.5);
  EXPECT_DOUBLE_EQ(better.metrics.at("time_out").mean, 0.0);
  // baseline: seed 0 times out in 3 of 4 scenarios, seed 1 in 2.
  EXPECT_DOUBLE_EQ(report.models[1].metrics.at("time_out").mean, 62.5);
  // Unbounded: Student-t over the seed means 10 and 20 (sd 7.07, t(0.975, 1) = 12.706).
  const MetricEstimate& cte = better.metrics.at("cross_track_error");
  EXPECT_EQ(cte.method, "t over seeds");
  EXPECT_NEAR(cte.ci.high - cte.mean, 12.7062 * 5.0, 1e-3);
  // The return is unbounded too: seed means 100 and (90 * 3 - 10) / 4 = 65.
  const MetricEstimate& episode_return = better.metrics.at("return");
  EXPECT_EQ(episode_return.method, "t over seeds");
  EXPECT_DOUBLE_EQ(episode_return.mean, 82.5);

  const ModelSummary& agent = report.models[2];
  EXPECT_EQ(agent.name, "ref.agent");
  EXPECT_EQ(agent.metrics.at("collision").method, "Wilson");  // 1 of 4 episodes
  EXPECT_NEAR(agent.metrics.at("collision").ci.low, 4.5586, 1e-3);
  EXPECT_NEAR(agent.metrics.at("collision").ci.high, 69.9358, 1e-3);
  EXPECT_EQ(agent.metrics.at("progress").method, "bootstrap");
  EXPECT_GE(agent.metrics.at("progress").ci.low, 50.0);
  EXPECT_LE(agent.metrics.at("progress").ci.high, 100.0);

  // Improvements: better over baseline and over the agent; baseline over the agent only.
  ASSERT_EQ(report.improvements.size(), 3U);
  const ImprovementSummary& over_baseline = report.improvements[0];
  EXPECT_EQ(over_baseline.over, "baseline");
  EXPECT_DOUBLE_EQ(over_baseline.metrics.at("progress").probability, 1.0);
  EXPECT_DOUBLE_EQ(over_baseline.metrics.at("cross_track_error").probability, 1.0);  // lower cte
  // No episode reached the goal: progress to the finish is progress itself.
  EXPECT_DOUBLE_EQ(over_baseline.metrics.at(kProgressToFinish).probability, 1.0);
  // Collisions, lower is better, per scenario over the 2 x 2 seed pairs:
  // t0: better {0, 0} vs {100, 100}: 4 wins; t1: {0, 0} vs {0, 100}: 2 wins + 2 ties; t2: 4 ties;
  // t3: {0, 100} vs {0, 0}: 2 ties, 2 losses. (4 + 3 + 2 + 1) / 16.
  EXPECT_DOUBLE_EQ(over_baseline.metrics.at("collision").probability, 10.0 / 16.0);
  // Return, higher is better; per scenario (seed 0, seed 1), better: t0-t2 (100, 90), t3 (100,
  // -10); baseline: t0 (-20, -30), t1 (80, -30), t2-t3 (80, 70). 4 wins on each of t0-t2, 2 on t3.
  EXPECT_DOUBLE_EQ(over_baseline.metrics.at("return").probability, 14.0 / 16.0);
  EXPECT_EQ(report.improvements[1].over, "ref.agent");
  EXPECT_EQ(report.improvements[2].model, "baseline");
  // Each configuration against the single agent only, not against the other configuration.
  ASSERT_EQ(report.agents_among_seeds.size(), 2U);
  EXPECT_EQ(report.agents_among_seeds[0].config, "better");
  EXPECT_EQ(report.agents_among_seeds[0].agent, "ref.agent");
  EXPECT_EQ(report.agents_among_seeds[1].config, "baseline");
}

// A configuration that names its own compare_to is compared with that one, not the study's.
TEST(StudyReportTest, AConfigurationIsComparedWithItsOwnReference) {
  StudySpec spec;
  spec.ppo_seeds = 1;
  spec.ppo_configs = {{"cnn", "baseline", "", true, {}},
                      {"cnn_variant", "baseline", "", true, {}, 0, "cnn"},
                      {"other", "baseline", "", true, {}}};
  ScenarioSetResults results;
  results.episodes = 4;
  results.models["cnn.seed_0"] = Episodes({80, 80, 80, 80}, {30, 30, 30, 30}, {0, 0, 0, 0});
  results.models["cnn_variant.seed_0"] = Episodes({90, 70, 90, 80}, {20, 40, 20, 30}, {0, 0, 0, 0});
  results.models["other.seed_0"] = Episodes({60, 60, 60, 60}, {50, 50, 50, 50}, {0, 0, 0, 0});
  const ScenarioSetReport report = SummariseScenarioSet(spec, results, "other");
  // cnn over the study's "other"; cnn_variant over its own "cnn" only; "other" over nothing.
  ASSERT_EQ(report.improvements.size(), 2U);
  EXPECT_EQ(report.improvements[0].model, "cnn");
  EXPECT_EQ(report.improvements[0].over, "other");
  EXPECT_EQ(report.improvements[1].model, "cnn_variant");
  EXPECT_EQ(report.improvements[1].over, "cnn");
  // Progress against cnn per scenario: a win, a loss, a win, a tie.
  EXPECT_DOUBLE_EQ(report.improvements[1].metrics.at("progress").probability, 2.5 / 4.0);
  // Cross-track error, lower is better: the same pattern.
  EXPECT_DOUBLE_EQ(report.improvements[1].metrics.at("cross_track_error").probability, 2.5 / 4.0);
}

// An ensemble kind is summarised over its ensembles and compared as a configuration is.
TEST(StudyReportTest, EnsembleKindsAreSummarisedOverTheirEnsembles) {
  StudySpec spec;
  spec.ppo_seeds = 2;
  spec.ppo_configs = {{"baseline", "baseline", "", true, {}}};
  spec.ensembles = {{"pair", {"baseline", "baseline"}, 1, std::nullopt, std::nullopt}};
  ScenarioSetResults results;
  results.episodes = 2;
  results.models["baseline.seed_0"] = Episodes({80, 80}, {30, 30}, {100, 0});
  results.models["baseline.seed_1"] = Episodes({70, 70}, {40, 40}, {100, 100});
  results.models["pair.seed_0"] = Episodes({100, 90}, {10, 20}, {0, 0});
  results.models["ref.agent"] = Episodes({100, 50}, {15, 15}, {0, 100});
  const ScenarioSetReport report = SummariseScenarioSet(spec, results, "baseline");
  ASSERT_EQ(report.models.size(), 3U);
  EXPECT_EQ(report.models[1].name, "pair");
  EXPECT_EQ(report.models[1].seeds, 1);
  EXPECT_DOUBLE_EQ(report.models[1].metrics.at("progress").mean, 95.0);
  // baseline over the agent; the pair over baseline and over the agent.
  ASSERT_EQ(report.improvements.size(), 3U);
  EXPECT_EQ(report.improvements[1].model, "pair");
  EXPECT_EQ(report.improvements[1].over, "baseline");
  // Collisions per scenario against baseline's seeds: t0 {0} vs {100, 100}, 2 wins; t1 {0} vs
  // {0, 100}, a tie and a win.
  EXPECT_DOUBLE_EQ(report.improvements[1].metrics.at("collision").probability, 3.5 / 4.0);
  EXPECT_EQ(report.improvements[2].over, "ref.agent");
  // Against its own members (baseline's seeds 0 and 1): progress 95 - 75, collisions 0 - 75.
  ASSERT_EQ(report.ensemble_gains.size(), 1U);
  EXPECT_EQ(report.ensemble_gains[0].ensemble, "pair");
  EXPECT_DOUBLE_EQ(report.ensemble_gains[0].metrics.at("progress").mean, 20.0);
  EXPECT_DOUBLE_EQ(report.ensemble_gains[0].metrics.at("collision").mean, -75.0);
  EXPECT_EQ(report.ensemble_gains[0].metrics.at("collision").count, 1U);
}

// The report's words for each way members share the helm: the mean, the range rule, one relief at
// a stall for good, and later members from later stalls.
TEST(StudyReportTest, EnsembleRulesAreDescribedAsTheyAct) {
  const std::string pace =
      "the vessel's pace towards the look-ahead point, averaged over 200 steps, falls below 0.1 "
      "m/s";
  EnsembleSpec ensemble{"kind", {"near", "far"}, 1, std::nullopt, std::nullopt};
  EXPECT_EQ(DescribeEnsembleRule(ensemble), "");
  ensemble.near_within_m = 20.0;
  EXPECT_EQ(DescribeEnsembleRule(ensemble),
            ", the first steering within 20 m of an obstacle, the second otherwise");
  ensemble.stall = StallRule{0.1, 200};
  EXPECT_EQ(DescribeEnsembleRule(ensemble),
            ", the first steering within 20 m of an obstacle, the second otherwise and for the "
            "rest of the episode once " +
                pace);
  ensemble.members.push_back("rescue");
  const std::string later =
      ", each later member from the next stall on, the last to the episode's end (the average "
      "restarts at each stall)";
  EXPECT_EQ(DescribeEnsembleRule(ensemble),
            ", the first steering within 20 m of an obstacle, the second otherwise and from the "
            "step " +
                pace + later);
  ensemble.near_within_m.reset();
  EXPECT_EQ(DescribeEnsembleRule(ensemble),
            ", the first steering, the second from the step " + pace + later);
}

// Where both reach the goal the last step decides; elsewhere, the failures.
TEST(StudyReportTest, TheProgressComparisonIsSplitWhereBothReachTheGoal) {
  ModelEpisodes a = Episodes({98, 60, 99}, {10, 10, 10}, {0, 0, 0});
  ModelEpisodes b = Episodes({99, 50, 99}, {10, 10, 10}, {0, 100, 0});
  a["goal"] = {100, 0, 100};
  b["goal"] = {100, 0, 100};
  const ProgressAtGoalSplit split = SplitProgressAtGoal({&a}, {&b});
  EXPECT_DOUBLE_EQ(split.both_at_goal_share, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(split.both_at_goal_probability, 0.25);  // a loss and a tie
  EXPECT_DOUBLE_EQ(split.elsewhere_probability, 1.0);
  // Over seed pairs: a second seed of b that fails the first scenario moves it out of the goal
  // part: 3 of 6 pairs at the goal (a loss and two ties), 3 elsewhere (a wins all).
  ModelEpisodes b_failing = b;
  b_failing["goal"] = {0, 0, 100};
  b_failing["progress"] = {70, 50, 99};
  const ProgressAtGoalSplit seeds = SplitProgressAtGoal({&a}, {&b, &b_failing});
  EXPECT_DOUBLE_EQ(seeds.both_at_goal_share, 0.5);
  EXPECT_DOUBLE_EQ(seeds.both_at_goal_probability, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(seeds.elsewhere_probability, 1.0);
}

// To the finish every goal counts 100 %: a's earlier last step at the goal (98 against b's 99)
// becomes a tie, so a, which gets farther where both fail, wins 2 of 3 instead of 1.5.
TEST(StudyReportTest, ProgressToTheFinishCountsEveryGoalAsTheWholePath) {
  ModelEpisodes a = Episodes({98, 60, 99}, {10, 10, 10}, {0, 0, 0});
  ModelEpisodes b = Episodes({99, 50, 99}, {10, 10, 10}, {0, 100, 0});
  a["goal"] = {100, 0, 100};
  b["goal"] = {100, 0, 100};
  EXPECT_EQ(ProgressToFinish({&a, &b}), (SeedScores{{100, 60, 100}, {100, 50, 100}}));
  EXPECT_DOUBLE_EQ(ProbabilityOfImprovement({a.at("progress")}, {b.at("progress")}), 0.5);
  EXPECT_DOUBLE_EQ(ProbabilityOfImprovement(ProgressToFinish({&a}), ProgressToFinish({&b})),
                   2.0 / 3.0);
}

// Over a kind's ensembles: ensemble k against the runs it holds, not against other runs.
TEST(StudyReportTest, AnEnsembleIsComparedWithItsOwnMembers) {
  StudySpec spec;
  spec.ppo_seeds = 2;
  spec.ppo_configs = {{"a", "baseline", "", true, {}}, {"b", "baseline", "", true, {}}};
  const EnsembleSpec pair{"pair", {"a", "b"}, 2, std::nullopt, std::nullopt};
  ScenarioSetResults results;
  results.episodes = 1;
  results.models["a.seed_0"] = Episodes({60}, {10}, {0});
  results.models["b.seed_0"] = Episodes({80}, {30}, {0});
  results.models["a.seed_1"] = Episodes({90}, {20}, {0});
  results.models["b.seed_1"] = Episodes({100}, {40}, {0});
  results.models["pair.seed_0"] = Episodes({75}, {20}, {0});   // +5 over its members' 70
  results.models["pair.seed_1"] = Episodes({100}, {30}, {0});  // +5 over its members' 95
  const EnsembleGain gain = MeasureEnsembleGain(pair, results);
  const MeanConfidenceInterval& progress = gain.metrics.at("progress");
  EXPECT_DOUBLE_EQ(progress.mean, 5.0);
  EXPECT_DOUBLE_EQ(progress.low, 5.0);  // the same gain twice: no spread
  EXPECT_DOUBLE_EQ(gain.metrics.at("cross_track_error").mean, 0.0);
}

// Three seeds with cte 10, 20 and 30 m (mean 20, sd 10): one more seed lands within 20 +-
// t(0.975, 2) * 10 * sqrt(4 / 3) = 20 +- 49.68 m; progress 98, 99 and 100 % (sd 1) within 99 +-
// 4.97, clipped at 100; collisions 0 % on every seed, a zero-width interval.
TEST(StudyReportTest, WhereASingleAgentFallsAmongTheSeeds) {
  const StudySpec spec = OneConfiguration(3);
  ScenarioSetResults results;
  results.episodes = 2;
  results.models["mine.seed_0"] = Episodes({98, 98}, {10, 10}, {0, 0});
  results.models["mine.seed_1"] = Episodes({99, 99}, {20, 20}, {0, 0});
  results.models["mine.seed_2"] = Episodes({100, 100}, {30, 30}, {0, 0});
  results.models["ref.agent"] = Episodes({100, 98}, {12, 18}, {0, 100});

  const ScenarioSetReport report = SummariseScenarioSet(spec, results, "");
  ASSERT_EQ(report.agents_among_seeds.size(), 1U);
  const AgentAmongSeeds& row = report.agents_among_seeds[0];
  const double t = 4.302652730;  // t(0.975, 2)
  const SeedPlacement& cte = row.metrics.at("cross_track_error");
  EXPECT_DOUBLE_EQ(cte.value, 15.0);
  EXPECT_NEAR(cte.prediction.low, 20.0 - t * 10.0 * std::sqrt(4.0 / 3.0), 1e-6);
  EXPECT_NEAR(cte.prediction.high, 20.0 + t * 10.0 * std::sqrt(4.0 / 3.0), 1e-6);
  EXPECT_TRUE(cte.inside);
  EXPECT_EQ(cte.seeds_better, 1);  // only the 10 m seed keeps closer to the path
  EXPECT_EQ(cte.seeds_worse, 2);
  EXPECT_EQ(cte.seeds, 3);
  // Ranked second of 4: at most one of ours better with chance 2/4, twice that, capped.
  EXPECT_DOUBLE_EQ(cte.rank_p, 1.0);
  const SeedPlacement& progress = row.metrics.at("progress");
  EXPECT_DOUBLE_EQ(progress.value, 99.0);
  EXPECT_NEAR(progress.prediction.low, 99.0 - t * std::sqrt(4.0 / 3.0), 1e-6);
  EXPECT_DOUBLE_EQ(progress.prediction.high, 100.0);  // clipped
  EXPECT_TRUE(progress.inside);
  EXPECT_EQ(progress.seeds_better, 1);  // the tie at 99 % does not count
  EXPECT_EQ(progress.seeds_worse, 1);
  EXPECT_DOUBLE_EQ(progress.rank_p, 1.0);  // the tie counts on both sides: 2 * 3/4, capped
  const SeedPlacement& collision = row.metrics.at("collision");
  EXPECT_DOUBLE_EQ(collision.value, 50.0);
  EXPECT_DOUBLE_EQ(collision.prediction.low, 0.0);
  EXPECT_DOUBLE_EQ(collision.prediction.high, 0.0);
  EXPECT_FALSE(collision.inside);
  EXPECT_EQ(collision.seeds_better, 3);
  EXPECT_EQ(collision.seeds_worse, 0);
  // Worse than every seed: one more seed does this badly with chance 1/4; two-sided 2/4, the
  // least three seeds can give.
  EXPECT_DOUBLE_EQ(collision.rank_p, 0.5);
}

// Twenty seeds at 20, 21, ..., 39 m and an agent at 20.5 m, beaten by one seed: were it one more
// seed, at most one of ours would beat it with chance 2/21; two-sided, 4/21.
TEST(StudyReportTest, RankTestOfASingleAgentAmongManySeeds) {
  const StudySpec spec = OneConfiguration(20);
  ScenarioSetResults results;
  results.episodes = 1;
  for (int k = 0; k < 20; ++k) {
    results.models["mine.seed_" + std::to_string(k)] = Episodes({99}, {20.0 + k}, {0});
  }
  results.models["ref.agent"] = Episodes({99}, {20.5}, {0});
  const ScenarioSetReport report = SummariseScenarioSet(spec, results, "");
  const SeedPlacement& cte = report.agents_among_seeds.at(0).metrics.at("cross_track_error");
  EXPECT_EQ(cte.seeds_better, 1);
  EXPECT_EQ(cte.seeds_worse, 19);
  EXPECT_DOUBLE_EQ(cte.rank_p, 4.0 / 21.0);
}

// Two seeds, three scenarios: seed 0 collides at 40 % and times out at 20 % on scenario 1, seed 1
// times out there too; the other episodes end at 99 %.
TEST(StudyReportTest, WhereTheProgressAndTheCrossTrackErrorGo) {
  const ModelEpisodes seed_0 = Episodes({40, 20, 99}, {10, 50, 20}, {100, 0, 0});
  const ModelEpisodes seed_1 = Episodes({99, 20, 99}, {20, 30, 20}, {0, 0, 0});
  const OutcomeBreakdown o = BreakDownOutcomes({&seed_0, &seed_1});
  // Of 6 episodes: 1 collision (60 points lost, 10 m), 2 time-outs (160 points, 80 m), 3 at 99 %.
  EXPECT_NEAR(o.collision.share, 100.0 / 6, 1e-12);
  EXPECT_NEAR(o.collision.progress_lost, 60.0 / 6, 1e-12);
  EXPECT_NEAR(o.collision.cross_track_error, 10.0 / 6, 1e-12);
  EXPECT_NEAR(o.time_out.share, 200.0 / 6, 1e-12);
  EXPECT_NEAR(o.time_out.progress_lost, 160.0 / 6, 1e-12);
  EXPECT_NEAR(o.time_out.cross_track_error, 80.0 / 6, 1e-12);
  EXPECT_NEAR(o.rest.share, 50.0, 1e-12);
  EXPECT_NEAR(o.rest.progress_lost, 0.5, 1e-12);
  EXPECT_NEAR(o.rest.cross_track_error, 10.0, 1e-12);
  // The parts add up to 100 - mean progress (377 / 6).
  EXPECT_NEAR(o.collision.progress_lost + o.time_out.progress_lost + o.rest.progress_lost,
              100.0 - 377.0 / 6, 1e-12);
  EXPECT_EQ(o.time_out_scenarios, 1);
  EXPECT_EQ(o.time_out_every_seed, 1);
  EXPECT_EQ(BreakDownOutcomes({&seed_0}).time_out_every_seed, 1);
  const ModelEpisodes no_time_out = Episodes({99, 99, 99}, {20, 20, 20}, {0, 0, 0});
  EXPECT_EQ(BreakDownOutcomes({&seed_0, &no_time_out}).time_out_every_seed, 0);
}

}  // namespace
}  // namespace colav

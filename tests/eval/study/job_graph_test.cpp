#include "eval/study/job_graph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;

StudySpec TinySpec(const TemporaryFolder& folder) {
  StudySpec spec;
  spec.name = "tiny";
  spec.vaes = {{"shallow", "shallow", 2, {}}};
  spec.ppo_seeds = 3;
  spec.ppo_steps = 4096;
  spec.ppo_configs = {{"locked", "vae-shallow", "shallow", true, {}},
                      {"log", "vae-shallow", "shallow", false, {"env.closeness=log"}, 8192},
                      {"baseline", "baseline", "", true, {}}};
  spec.evaluation.episodes = 20;
  spec.evaluation.paper_episodes = 5;
  const std::filesystem::path agent = folder / "agent.pt";
  std::ofstream(agent) << "x";
  std::ofstream(agent.string() + ".yaml") << "env:\n  closeness: log\n";
  spec.evaluation.reference_agents = {agent};
  return spec;
}

const StudyJob& Find(const std::vector<StudyJob>& jobs, const std::string& id) {
  const auto job =
      std::find_if(jobs.begin(), jobs.end(), [&](const StudyJob& j) { return j.id == id; });
  EXPECT_NE(job, jobs.end()) << id;
  return *job;
}

bool Has(const std::vector<std::string>& args, const std::vector<std::string>& run) {
  return std::search(args.begin(), args.end(), run.begin(), run.end()) != args.end();
}

TEST(JobGraphTest, JobsDependenciesAndArguments) {
  const TemporaryFolder folder;
  const std::vector<StudyJob> jobs = BuildJobGraph(TinySpec(folder), "/s");
  // data, 1 VAE, 3 x 3 PPO runs, a training figure per configuration, one evaluation per
  // scenario set (study, paper).
  EXPECT_EQ(jobs.size(), 1U + 1U + 9U + 3U + 2U);
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    for (const std::size_t d : jobs[i].dependencies) EXPECT_LT(d, i) << jobs[i].id;
  }
  const StudyJob& run = Find(jobs, "ppo/locked/seed_2");
  EXPECT_EQ(run.program, "train_ppo");
  // PPO seed 2 uses VAE seed 2 mod 2 = 0; seeds and steps as the study says.
  EXPECT_TRUE(Has(run.args, {"--encoder", "/s/vae/shallow/seed_0/encoder.pt", "--locked"}));
  EXPECT_TRUE(Has(run.args, {"--steps", "4096", "--seed", "2", "--out", "/s/ppo/locked/seed_2"}));
  EXPECT_EQ(run.resume_args, (std::vector<std::string>{"--resume", "/s/ppo/locked/seed_2"}));
  EXPECT_EQ(jobs[run.dependencies.at(0)].id, "vae/shallow");
  EXPECT_TRUE(Find(jobs, "ppo/baseline/seed_0").dependencies.empty());
  EXPECT_TRUE(Has(Find(jobs, "ppo/log/seed_0").args, {"--unlocked"}));
  EXPECT_TRUE(Has(Find(jobs, "ppo/log/seed_0").args, {"--set", "env.closeness=log"}));
  EXPECT_TRUE(Has(Find(jobs, "ppo/log/seed_0").args, {"--steps", "8192"}));  // its own
  const StudyJob& figure = Find(jobs, "figures/training/locked");
  EXPECT_EQ(figure.program, "plot_training");
  EXPECT_EQ(figure.dependencies.size(), 3U);
  EXPECT_TRUE(Has(figure.args, {"--run", "seed_2=/s/ppo/locked/seed_2"}));
  EXPECT_EQ(figure.complete_marker, "/s/figures/training_locked.png");
}

TEST(JobGraphTest, EachScenarioSetIsOnePairedEvaluationOfEveryModel) {
  const TemporaryFolder folder;
  const std::vector<EvaluationGroup> groups = EvaluationGroups(TinySpec(folder), "/s");
  ASSERT_EQ(groups.size(), 2U);
  EXPECT_EQ(groups[0].scenario_set, "study");
  ASSERT_EQ(groups[0].models.size(), 10U);  // 3 configurations x 3 seeds, the reference agent
  EXPECT_EQ(groups[0].models[0], "locked.seed_0");
  EXPECT_EQ(groups[0].models[3], "log.seed_0");
  EXPECT_EQ(groups[0].models[9], "ref.agent");
  EXPECT_EQ(groups[1].scenario_set, "paper");
  EXPECT_EQ(groups[1].episodes, 5);
  EXPECT_EQ(groups[1].seed, 0U);
  const std::vector<StudyJob> jobs = BuildJobGraph(TinySpec(folder), "/s");
  const StudyJob& evaluation = Find(jobs, "eval/study");
  EXPECT_EQ(evaluation.dependencies.size(), 9U);  // every PPO run; the agent file exists
  EXPECT_TRUE(Has(evaluation.args, {"--episodes", "20", "--seed", "1"}));
  // Complete only when its summary lists exactly these models.
  EXPECT_EQ(evaluation.expected_models, groups[0].models);
  // Each policy brings its own observation settings: the evaluation sets none.
  EXPECT_FALSE(Has(evaluation.args, {"--set"}));
  // A study that gained models evaluates again, taking the unchanged models' episodes.
  EXPECT_TRUE(
      Has(evaluation.args, {"--out", "/s/eval/study", "--overwrite", "--reuse", "/s/eval/study"}));
}

// Validation scenarios are one more paired evaluation of every model, on their own master seed.
TEST(JobGraphTest, ValidationScenariosAreAThirdEvaluationOnTheirOwnSeed) {
  const TemporaryFolder folder;
  StudySpec spec = TinySpec(folder);
  spec.evaluation.validation_episodes = 30;
  spec.evaluation.validation_seed = 7;
  const std::vector<EvaluationGroup> groups = EvaluationGroups(spec, "/s");
  ASSERT_EQ(groups.size(), 3U);
  EXPECT_EQ(groups[2].scenario_set, "validation");
  EXPECT_EQ(groups[2].episodes, 30);
  EXPECT_EQ(groups[2].seed, 7U);
  EXPECT_EQ(groups[2].models, groups[0].models);
  const std::vector<StudyJob> jobs = BuildJobGraph(spec, "/s");
  const StudyJob& evaluation = Find(jobs, "eval/validation");
  EXPECT_TRUE(Has(evaluation.args, {"--episodes", "30", "--seed", "7"}));
  EXPECT_TRUE(Has(evaluation.args, {"--out", "/s/eval/validation"}));
}

// Each ensemble is a job after the runs it averages, and a model of the evaluations after them.
TEST(JobGraphTest, EnsemblesAreBuiltFromTheirRunsAndEvaluatedWithThem) {
  const TemporaryFolder folder;
  StudySpec spec = TinySpec(folder);
  spec.ensembles = {{"mix", {"locked", "baseline", "locked"}, 1, std::nullopt, std::nullopt}};
  const std::vector<StudyJob> jobs = BuildJobGraph(spec, "/s");
  const StudyJob& ensemble = Find(jobs, "ensembles/mix/seed_0");
  EXPECT_EQ(ensemble.program, "ensemble_policy");
  EXPECT_EQ(ensemble.args,
            (std::vector<std::string>{
                "--out", "/s/ensembles/mix/seed_0/policy.pt", "/s/ppo/locked/seed_0/policy.pt",
                "/s/ppo/baseline/seed_0/policy.pt", "/s/ppo/locked/seed_1/policy.pt"}));
  EXPECT_EQ(ensemble.complete_marker, "/s/ensembles/mix/seed_0/policy.pt");
  std::vector<std::string> dependencies;
  for (const std::size_t d : ensemble.dependencies) dependencies.push_back(jobs[d].id);
  EXPECT_EQ(dependencies, (std::vector<std::string>{"ppo/locked/seed_0", "ppo/baseline/seed_0",
                                                    "ppo/locked/seed_1"}));
  const StudyJob& evaluation = Find(jobs, "eval/study");
  EXPECT_TRUE(Has(evaluation.args,
                  {"--policy", "/s/ensembles/mix/seed_0/policy.pt", "--name", "mix.seed_0"}));
  EXPECT_NE(std::find(evaluation.dependencies.begin(), evaluation.dependencies.end(),
                      static_cast<std::size_t>(&ensemble - jobs.data())),
            evaluation.dependencies.end());
  EXPECT_EQ(evaluation.expected_models.at(9), "mix.seed_0");  // after the runs, before the agent
  // Two helmsmen: the first near obstacles, the second once the vessel stalls.
  spec.ensembles = {{"helm", {"locked", "baseline"}, 3, 30.5, StallRule{0.15, 150}}};
  EXPECT_EQ(Find(BuildJobGraph(spec, "/s"), "ensembles/helm/seed_2").args,
            (std::vector<std::string>{"--out", "/s/ensembles/helm/seed_2/policy.pt",
                                      "--near-within", "30.5", "--stall-pace", "0.15",
                                      "--stall-steps", "150", "/s/ppo/locked/seed_2/policy.pt",
                                      "/s/ppo/baseline/seed_2/policy.pt"}));
}

// Each student is a distill_policy job after its teacher and the run it starts from, finished
// when its summary says so, continued from its state, and a model of the evaluations.
TEST(JobGraphTest, StudentsAreDistilledFromTheirTeachersAndEvaluatedWithThem) {
  const TemporaryFolder folder;
  StudySpec spec = TinySpec(folder);
  spec.ensembles = {{"mix", {"log", "locked", "locked"}, 1, std::nullopt, std::nullopt}};
  spec.students = {{"taught", "mix", "locked", {"--traps", "8"}, 1, ""},
                   {"from_log", "log", "baseline", {}, 3, ""}};
  const std::vector<StudyJob> jobs = BuildJobGraph(spec, "/s");
  const StudyJob& taught = Find(jobs, "students/taught/seed_0");
  EXPECT_EQ(taught.program, "distill_policy");
  const std::vector<std::string> args = {"/s/ensembles/mix/seed_0/policy.pt",
                                         "/s/ppo/locked/seed_0/policy.pt",
                                         "--out",
                                         "/s/students/taught/seed_0/policy.pt",
                                         "--seed",
                                         "0",
                                         "--threads",
                                         "1",
                                         "--traps",
                                         "8"};
  EXPECT_EQ(taught.args, args);
  std::vector<std::string> resume = args;
  resume.emplace_back("--resume");
  EXPECT_EQ(taught.resume_args, resume);
  EXPECT_EQ(taught.resume_marker, "/s/students/taught/seed_0/policy.pt.state");
  EXPECT_EQ(taught.complete_marker, "/s/students/taught/seed_0/policy.pt.json");
  EXPECT_EQ(taught.recorded_settings, taught.complete_marker);  // its settings, as it ran
  std::vector<std::string> dependencies;
  for (const std::size_t d : taught.dependencies) dependencies.push_back(jobs[d].id);
  EXPECT_EQ(dependencies, (std::vector<std::string>{"ensembles/mix/seed_0", "ppo/locked/seed_0"}));
  // A configuration as the teacher: its run k, the start's seed k.
  const StudyJob& from_log = Find(jobs, "students/from_log/seed_2");
  EXPECT_TRUE(
      Has(from_log.args, {"/s/ppo/log/seed_2/policy.pt", "/s/ppo/baseline/seed_2/policy.pt",
                          "--out", "/s/students/from_log/seed_2/policy.pt", "--seed", "2"}));
  EXPECT_FALSE(from_log.check_configuration);  // seed 0 stands for its siblings
  const StudyJob& evaluation = Find(jobs, "eval/study");
  EXPECT_TRUE(Has(evaluation.args,
                  {"--policy", "/s/students/taught/seed_0/policy.pt", "--name", "taught.seed_0"}));
  EXPECT_NE(std::find(evaluation.dependencies.begin(), evaluation.dependencies.end(),
                      static_cast<std::size_t>(&taught - jobs.data())),
            evaluation.dependencies.end());
  // After the runs and the ensemble, before the reference agent.
  EXPECT_EQ(evaluation.expected_models.at(10), "taught.seed_0");
  EXPECT_EQ(evaluation.expected_models.at(13), "from_log.seed_2");
  EXPECT_EQ(evaluation.expected_models.at(14), "ref.agent");
}

// Each fine-tune is a train_ppo job with the settings of the run its student started from (that
// run's seed, encoder and overrides), then policy.init = the student and the kind's own
// overrides, after the student; its training curves are drawn and it is evaluated with the rest.
TEST(JobGraphTest, FineTunesContinueTheirStudentsWithTheirStartsSettings) {
  const TemporaryFolder folder;
  StudySpec spec = TinySpec(folder);
  spec.ppo_overrides = {"ppo.gamma=0.99"};
  spec.ensembles = {{"mix", {"locked", "locked", "log"}, 1, std::nullopt, std::nullopt}};
  spec.students = {{"taught", "mix", "log", {}, 1, ""}};
  spec.fine_tunes = {{"tuned", "taught", {"ppo.learning_rate=2e-5"}, 1000, 1, "taught"},
                     {"long", "taught", {}, 0, 1, ""}};
  const std::vector<StudyJob> jobs = BuildJobGraph(spec, "/s");
  const StudyJob& tuned = Find(jobs, "fine_tunes/tuned/seed_0");
  EXPECT_EQ(tuned.program, "train_ppo");
  // The ensemble's member "log" is its run 0; log's encoder is unlocked, VAE seed 0.
  const std::vector<std::string> args = {"--extractor",
                                         "vae-shallow",
                                         "--encoder",
                                         "/s/vae/shallow/seed_0/encoder.pt",
                                         "--unlocked",
                                         "--steps",
                                         "1000",
                                         "--seed",
                                         "0",
                                         "--out",
                                         "/s/fine_tunes/tuned/seed_0",
                                         "--set",
                                         "ppo.gamma=0.99",
                                         "--set",
                                         "env.closeness=log",
                                         "--set",
                                         "policy.init=/s/students/taught/seed_0/policy.pt",
                                         "--set",
                                         "ppo.learning_rate=2e-5"};
  EXPECT_EQ(tuned.args, args);
  EXPECT_EQ(tuned.resume_args,
            (std::vector<std::string>{"--resume", "/s/fine_tunes/tuned/seed_0"}));
  EXPECT_EQ(tuned.complete_marker, "/s/fine_tunes/tuned/seed_0/summary.json");
  EXPECT_TRUE(tuned.check_configuration);
  std::vector<std::string> dependencies;
  for (const std::size_t d : tuned.dependencies) dependencies.push_back(jobs[d].id);
  EXPECT_EQ(dependencies, (std::vector<std::string>{"vae/shallow", "students/taught/seed_0"}));
  // Without steps of its own: the start configuration's (log trains 8192).
  EXPECT_TRUE(Has(Find(jobs, "fine_tunes/long/seed_0").args, {"--steps", "8192"}));
  const StudyJob& figure = Find(jobs, "figures/training/tuned");
  EXPECT_TRUE(Has(figure.args, {"--run", "seed_0=/s/fine_tunes/tuned/seed_0"}));
  EXPECT_EQ(jobs[figure.dependencies.at(0)].id, "fine_tunes/tuned/seed_0");
  const StudyJob& evaluation = Find(jobs, "eval/study");
  EXPECT_TRUE(Has(evaluation.args,
                  {"--policy", "/s/fine_tunes/tuned/seed_0/policy.pt", "--name", "tuned.seed_0"}));
  // After the students, before the reference agent.
  EXPECT_EQ(evaluation.expected_models.at(10), "taught.seed_0");
  EXPECT_EQ(evaluation.expected_models.at(11), "tuned.seed_0");
  EXPECT_EQ(evaluation.expected_models.at(12), "long.seed_0");
  EXPECT_EQ(evaluation.expected_models.at(13), "ref.agent");
}

// A student's estimated cost, which orders the jobs (the longest first) and makes the ETA, grows
// with the steps it plays: its iterations, worlds and steps per world.
TEST(JobGraphTest, AStudentsEstimatedCostGrowsWithTheStepsItPlays) {
  const TemporaryFolder folder;
  StudySpec spec = TinySpec(folder);
  spec.students = {{"plain", "log", "baseline", {}, 1, ""},
                   {"wide", "log", "baseline", {"--worlds", "64", "--traps", "8"}, 1, ""},
                   {"long", "log", "baseline", {"--iterations", "12", "--steps", "1024"}, 1, ""},
                   {"bad", "log", "baseline", {"--worlds", "x64"}, 1, ""}};
  const std::vector<StudyJob> jobs = BuildJobGraph(spec, "/s");
  const double plain = Find(jobs, "students/plain/seed_0").estimated_s;
  EXPECT_GT(plain, 0.0);
  EXPECT_DOUBLE_EQ(Find(jobs, "students/wide/seed_0").estimated_s, 2.0 * plain);
  EXPECT_DOUBLE_EQ(Find(jobs, "students/long/seed_0").estimated_s, 0.75 * plain);
  EXPECT_DOUBLE_EQ(Find(jobs, "students/bad/seed_0").estimated_s, plain);  // refused later
}

// A PPO run's estimated cost: its update share (0.6 at the paper's 4 passes) scales with its
// passes per rollout, and a memory multiplies the whole by 1.75; the last setting counts, study
// settings first, then the configuration's, then a fine-tune's.
TEST(JobGraphTest, APpoRunsEstimatedCostGrowsWithItsPassesAndItsMemory) {
  const TemporaryFolder folder;
  StudySpec spec = TinySpec(folder);
  spec.ppo_overrides = {"ppo.n_epochs=10"};
  spec.ppo_configs = {
      {"paper", "baseline", "", true, {"ppo.n_epochs=4"}},
      {"ten", "baseline", "", true, {}},
      {"two", "baseline", "", true, {"ppo.n_epochs=2"}},
      {"memory", "baseline", "", true, {"ppo.n_epochs=4", "policy.recurrent_size=64"}},
      {"bad", "baseline", "", true, {"ppo.n_epochs=x"}}};
  spec.ensembles = {{"pair", {"paper", "paper"}, 1, std::nullopt, std::nullopt}};
  spec.students = {{"taught", "pair", "paper", {}, 1, ""}};
  spec.fine_tunes = {{"tuned", "taught", {"ppo.n_epochs=2"}, 0, 1, ""}};
  const std::vector<StudyJob> jobs = BuildJobGraph(spec, "/s");
  const double paper = Find(jobs, "ppo/paper/seed_0").estimated_s;
  EXPECT_GT(paper, 0.0);
  EXPECT_DOUBLE_EQ(Find(jobs, "ppo/ten/seed_0").estimated_s, 1.9 * paper);  // 0.4 + 0.6 * 10/4
  EXPECT_DOUBLE_EQ(Find(jobs, "ppo/two/seed_0").estimated_s, 0.7 * paper);
  EXPECT_DOUBLE_EQ(Find(jobs, "ppo/memory/seed_0").estimated_s, 1.75 * paper);
  EXPECT_DOUBLE_EQ(Find(jobs, "ppo/bad/seed_0").estimated_s, paper);  // refused later
  EXPECT_DOUBLE_EQ(Find(jobs, "fine_tunes/tuned/seed_0").estimated_s, 0.7 * paper);
}

// An evaluation's estimated cost: per model and scenario a fixed part plus a part per network
// the model runs, near what studies' evaluations took beside another job: 15,000 episodes of
// single networks in 203-208 s, 20,000 of three-member ensembles in 440-447 s.
TEST(JobGraphTest, AnEvaluationsEstimatedCostGrowsWithTheNetworksItsModelsRun) {
  const TemporaryFolder folder;
  StudySpec spec = TinySpec(folder);
  spec.ppo_seeds = 5;
  spec.evaluation.episodes = 1000;
  spec.evaluation.reference_agents.clear();
  const double singles = Find(BuildJobGraph(spec, "/s"), "eval/study").estimated_s;
  EXPECT_NEAR(singles, 205.0, 20.0);  // 15 models
  const std::vector<std::string> members = {"locked", "baseline", "log"};
  spec.ensembles = {{"pair", {"locked", "baseline"}, 1, std::nullopt, std::nullopt}};
  const double pair = Find(BuildJobGraph(spec, "/s"), "eval/study").estimated_s - singles;
  spec.ensembles = {{"triple", members, 1, std::nullopt, std::nullopt}};
  const std::vector<EvaluationGroup> groups = EvaluationGroups(spec, "/s");
  std::vector<int> networks(15, 1);
  networks.push_back(3);
  EXPECT_EQ(groups[0].networks, networks);
  const double triple = Find(BuildJobGraph(spec, "/s"), "eval/study").estimated_s - singles;
  const double single = singles / 15.0;
  // Each network adds the same; a model costs more than its networks alone.
  EXPECT_NEAR(triple - pair, pair - single, 1e-9);
  EXPECT_GT(single, triple - pair);
  spec.ensembles = {{"a", members, 5, std::nullopt, std::nullopt},
                    {"b", members, 5, std::nullopt, std::nullopt},
                    {"c", members, 5, std::nullopt, std::nullopt},
                    {"d", members, 5, std::nullopt, std::nullopt}};
  EXPECT_NEAR(Find(BuildJobGraph(spec, "/s"), "eval/study").estimated_s - singles, 444.0, 44.0);
}

TEST(JobGraphTest, TheVaeFiguresAreAJobOnTheDatasetWhenAsked) {
  const TemporaryFolder folder;
  StudySpec spec = TinySpec(folder);
  const std::size_t without = BuildJobGraph(spec, "/s").size();
  spec.vae_figures = true;
  const std::vector<StudyJob> jobs = BuildJobGraph(spec, "/s");
  ASSERT_EQ(jobs.size(), without + 1);
  const StudyJob& figures = Find(jobs, "figures/vae");
  EXPECT_EQ(figures.program, "vae_figures");
  EXPECT_TRUE(Has(figures.args, {"--data", "/s/data/scans.h5", "--out", "/s/figures/vae"}));
  EXPECT_EQ(jobs[figures.dependencies.at(0)].id, "data");
}

}  // namespace
}  // namespace colav

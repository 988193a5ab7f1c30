#include "eval/study/study_spec.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "tests/src/project_paths.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;

// The repository's studies/ folder.
std::filesystem::path ShippedStudies() {
  return std::filesystem::path(testing_util::kSourceDir) / "studies";
}

std::filesystem::path WriteStudy(const TemporaryFolder& folder, const std::string& text) {
  const std::filesystem::path path = folder / "study.yaml";
  std::ofstream(path) << text;
  return path;
}

constexpr const char* kStudy = R"(name: tiny
dataset: {dataset.sim_scans: 100}
vaes:
  shallow: {model: shallow, seeds: 2, set: {training.epochs: 2}}
ppo:
  seeds: 3
  steps: 4096
  set: {ppo.n_envs: 2}
  configs:
    shallow_locked: {extractor: vae-shallow, vae: shallow, locked: true}
    shallow_log:
      extractor: vae-shallow
      vae: shallow
      set: {env.closeness: log}
      steps: 8192
      compare_to: shallow_locked
    baseline: {extractor: baseline}
evaluation: {episodes: 20, seed: 4, paper_episodes: 0}
)";

// kStudy with `keys` ("key: value, ...") added to its evaluation.
std::string WithEvaluationKeys(const std::string& keys) {
  const std::string evaluation = "paper_episodes: 0}";
  std::string text = kStudy;
  text.replace(text.find(evaluation), evaluation.size(), "paper_episodes: 0, " + keys + "}");
  return text;
}

TEST(StudySpecTest, ReadsEverySection) {
  const TemporaryFolder folder;
  const StudySpec spec = LoadStudySpec(WriteStudy(folder, kStudy));
  EXPECT_EQ(spec.name, "tiny");
  EXPECT_EQ(spec.dataset_overrides, Overrides{"dataset.sim_scans=100"});
  ASSERT_EQ(spec.vaes.size(), 1U);
  EXPECT_EQ(spec.vaes[0].seeds, 2);
  EXPECT_EQ(spec.vaes[0].overrides, Overrides{"training.epochs=2"});
  EXPECT_EQ(spec.ppo_seeds, 3);
  EXPECT_EQ(spec.ppo_steps, 4096);
  ASSERT_EQ(spec.ppo_configs.size(), 3U);
  EXPECT_EQ(spec.ppo_configs[0].name, "shallow_locked");  // file order
  EXPECT_EQ(spec.ppo_configs[1].overrides, Overrides{"env.closeness=log"});
  EXPECT_EQ(spec.ppo_configs[2].extractor, "baseline");
  EXPECT_EQ(spec.StepsOf(spec.ppo_configs[0]), 4096);  // the study's
  EXPECT_EQ(spec.StepsOf(spec.ppo_configs[1]), 8192);  // its own
  EXPECT_EQ(spec.evaluation.episodes, 20);
  EXPECT_EQ(spec.evaluation.seed, 4U);
  EXPECT_EQ(spec.evaluation.paper_episodes, 0);
  EXPECT_EQ(spec.evaluation.validation_episodes, 0);  // none unless asked for
  EXPECT_EQ(spec.evaluation.compare_to, "baseline");
  EXPECT_EQ(spec.ppo_configs[0].compare_to, "");  // the study's
  EXPECT_EQ(spec.ppo_configs[1].compare_to, "shallow_locked");
  EXPECT_FALSE(spec.vae_figures);
}

// Validation scenarios: their own count and master seed, which must not be the test's.
TEST(StudySpecTest, ReadsValidationScenariosApartFromTheTest) {
  const TemporaryFolder folder;
  std::string text = WithEvaluationKeys("validation_episodes: 30, validation_seed: 7");
  const StudySpec spec = LoadStudySpec(WriteStudy(folder, text));
  EXPECT_EQ(spec.evaluation.validation_episodes, 30);
  EXPECT_EQ(spec.evaluation.validation_seed, 7U);
  const std::string validation_seed = "validation_seed: 7";
  text.replace(text.find(validation_seed), validation_seed.size(),
               "validation_seed: 4");  // the test's seed
  const std::filesystem::path same = WriteStudy(folder, text);
  EXPECT_EQ(UserErrorMessage([&] { LoadStudySpec(same); }),
            same.string() +
                ": evaluation.validation_seed: equals evaluation.seed: the validation scenarios "
                "would be the test's");
}

// A goal bounds metrics of the report, each in its own units; the report measures it.
TEST(StudySpecTest, ReadsTheGoalAsBoundsOnTheReportsMetrics) {
  const TemporaryFolder folder;
  const StudySpec spec = LoadStudySpec(WriteStudy(
      folder, WithEvaluationKeys("goal: {progress: 97, cross_track_error: 17.5, collision: 0}")));
  const std::map<std::string, double> goal = {
      {"progress", 97.0}, {"cross_track_error", 17.5}, {"collision", 0.0}};
  EXPECT_EQ(spec.evaluation.goal, goal);
  EXPECT_TRUE(LoadStudySpec(WriteStudy(folder, kStudy)).evaluation.goal.empty());  // none
}

// Every study behind a claim (all but the quick start and the paper's table) loads, and measures
// as the claims need: 5 training seeds, the same 1,000 scenarios, the authors' three agents.
TEST(StudySpecTest, ShippedStudiesAreValid) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(ShippedStudies())) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".yaml" || name == "quickstart.yaml" ||
        name == "paper_results.yaml") {
      continue;
    }
    const StudySpec spec = LoadStudySpec(entry.path());
    EXPECT_GE(spec.ppo_seeds, 5) << name;  // the claims rule: 5 training seeds or more
    EXPECT_EQ(spec.evaluation.episodes, 1000) << name;
    EXPECT_EQ(spec.evaluation.seed, 1U) << name;
    EXPECT_EQ(spec.evaluation.reference_agents.size(), 3U) << name;
    ++checked;
  }
  EXPECT_GE(checked, 2);  // paper.yaml and ablation.yaml at least
  EXPECT_EQ(LoadStudySpec(ShippedStudies() / "ablation.yaml").evaluation.compare_to, "current");
}

TEST(StudySpecTest, ShippedQuickstartStudyIsValid) {
  const StudySpec spec = LoadStudySpec(ShippedStudies() / "quickstart.yaml");
  EXPECT_EQ(spec.name, "quickstart");
  EXPECT_EQ(spec.ppo_configs.size(), 2U);
  EXPECT_TRUE(std::filesystem::is_regular_file(spec.evaluation.paper_results));
}

TEST(StudySpecTest, SelectsConfigurationsAndSeeds) {
  const TemporaryFolder folder;
  const StudySpec spec = SelectModels(LoadStudySpec(WriteStudy(folder, kStudy)), {"baseline"}, 1);
  ASSERT_EQ(spec.ppo_configs.size(), 1U);
  EXPECT_TRUE(spec.vaes.empty());  // the baseline needs no VAE
  EXPECT_EQ(spec.ppo_seeds, 1);
  EXPECT_NE(UserErrorMessage([&] { SelectModels(spec, {"nope"}, 0); }).find("--only nope"),
            std::string::npos);
}

// Ensemble k of a kind of count n takes seed k + j n of a configuration listed for the j-th time;
// without a count, as many ensembles as the seeds give.
TEST(StudySpecTest, EnsemblesTakeDisjointRuns) {
  const TemporaryFolder folder;
  const StudySpec spec = LoadStudySpec(WriteStudy(folder, std::string(kStudy) + R"(ensembles:
  mixed: {members: [shallow_locked, baseline, shallow_locked]}
  pair: {members: [baseline, shallow_log], count: 2, near_within_m: 30.5}
  relieved: {members: [baseline, shallow_log], stall_pace_mps: 0.2, stall_steps: 50}
  rescued: {members: [baseline, shallow_log, shallow_locked], near_within_m: 20, stall_pace_mps: 0.1}
)"));
  ASSERT_EQ(spec.ensembles.size(), 4U);
  const EnsembleSpec& mixed = spec.ensembles[0];
  EXPECT_EQ(mixed.members,
            (std::vector<std::string>{"shallow_locked", "baseline", "shallow_locked"}));
  EXPECT_EQ(mixed.count, 1);  // 3 seeds give one pair of shallow_locked runs
  EXPECT_EQ(mixed.MemberSeed(0, 0), 0);
  EXPECT_EQ(mixed.MemberSeed(1, 0), 0);
  EXPECT_EQ(mixed.MemberSeed(2, 0), 1);
  EXPECT_FALSE(mixed.near_within_m);
  const EnsembleSpec& pair = spec.ensembles[1];
  EXPECT_EQ(pair.count, 2);
  EXPECT_EQ(pair.near_within_m, 30.5);
  EXPECT_EQ(pair.MemberSeed(0, 1), 1);
  EXPECT_EQ(pair.MaxCount(3), 3);
  EXPECT_FALSE(pair.stall);
  const EnsembleSpec& relieved = spec.ensembles[2];
  ASSERT_TRUE(relieved.stall);
  EXPECT_EQ(relieved.stall->pace_mps, 0.2);
  EXPECT_EQ(relieved.stall->steps, 50);
  // A third member with both rules: a relief at the second stall.
  const EnsembleSpec& rescued = spec.ensembles[3];
  EXPECT_EQ(rescued.members.size(), 3U);
  EXPECT_EQ(rescued.near_within_m, 20.0);
  ASSERT_TRUE(rescued.stall);
  EXPECT_EQ(rescued.stall->steps, 200);
  EXPECT_EQ(rescued.MemberSeed(2, 2), 2);
  EnsembleSpec quad{"quad", {"a", "b", "a", "b"}, 5, std::nullopt, std::nullopt};
  EXPECT_EQ(quad.MemberSeed(2, 3), 8);  // a's seeds 3 and 8, b's 3 and 8 in ensemble 3
  EXPECT_EQ(quad.MemberSeed(3, 3), 8);
  EXPECT_EQ(quad.MaxCount(10), 5);
  const std::vector<SeededModel> models = spec.SeededModels();
  ASSERT_EQ(models.size(), 7U);
  EXPECT_EQ(models[3].name, "mixed");
  EXPECT_EQ(models[4].seeds, 2);
  // Fewer seeds, fewer ensembles; a kind whose members are not all kept goes.
  const StudySpec one_seed = SelectModels(spec, {}, 1);
  ASSERT_EQ(one_seed.ensembles.size(), 3U);
  EXPECT_EQ(one_seed.ensembles[0].name, "pair");
  EXPECT_EQ(one_seed.ensembles[0].count, 1);
  // More seeds, more ensembles of a kind without a count; a count in the file stays.
  const StudySpec eight_seeds = SelectModels(spec, {}, 8);
  EXPECT_EQ(eight_seeds.ensembles[0].count, 4);  // mixed: 4 pairs of shallow_locked runs
  EXPECT_EQ(eight_seeds.ensembles[1].count, 2);  // pair: count 2 in the file
  EXPECT_EQ(eight_seeds.ensembles[3].count, 8);
  EXPECT_TRUE(SelectModels(spec, {"baseline", "shallow_locked"}, 0).ensembles.size() == 1U);
}

// Three configurations of 4 seeds, two of them recurrent (a student's start must be).
constexpr char kRecurrentConfigs[] = R"(ppo:
  seeds: 4
  set: {policy.recurrent_size: 8}
  configs:
    a: {}
    memory: {}
    flat: {set: {policy.recurrent_size: 0}}
)";

// Student k imitates the teacher's seed k and starts from the run ensemble k takes of `start`
// (seed k when `start` is not a member); its options become "--name value" pairs in file order.
TEST(StudySpecTest, StudiesDistilTeachersIntoStudents) {
  const TemporaryFolder folder;
  const StudySpec spec =
      LoadStudySpec(WriteStudy(folder, std::string(kRecurrentConfigs) + R"(ensembles:
  pair: {members: [a, memory, memory], stall_pace_mps: 0.1}
students:
  taught: {teacher: pair, start: memory, options: {traps: 8, stall-weight: 2.5}}
  from_flat: {teacher: flat, start: memory, compare_to: taught}
)"));
  ASSERT_EQ(spec.students.size(), 2U);
  const StudentSpec& taught = spec.students[0];
  EXPECT_EQ(taught.teacher, "pair");
  EXPECT_EQ(taught.count, 2);  // pair's ensembles
  EXPECT_EQ(taught.options, (std::vector<std::string>{"--traps", "8", "--stall-weight", "2.5"}));
  EXPECT_EQ(spec.StartSeed(taught, 1), 1);  // memory's first run in ensemble 1: seed 1
  const StudentSpec& from_flat = spec.students[1];
  EXPECT_EQ(from_flat.count, 4);  // flat's seeds
  EXPECT_EQ(spec.StartSeed(from_flat, 3), 3);
  EXPECT_EQ(from_flat.compare_to, "taught");
  const std::vector<SeededModel> models = spec.SeededModels();
  ASSERT_EQ(models.size(), 6U);  // 3 configurations, 1 ensemble kind, 2 kinds of student
  EXPECT_EQ(models[4].name, "taught");
  EXPECT_EQ(models[4].seeds, 2);
  EXPECT_EQ(models[5].compare_to, "taught");
  // Fewer seeds, fewer students; a student whose teacher or start goes, goes.
  const StudySpec two_seeds = SelectModels(spec, {}, 2);
  ASSERT_EQ(two_seeds.students.size(), 2U);
  EXPECT_EQ(two_seeds.students[0].count, 1);
  EXPECT_EQ(two_seeds.students[1].count, 2);
  const StudySpec without_flat = SelectModels(spec, {"a", "memory"}, 0);
  ASSERT_EQ(without_flat.students.size(), 1U);
  EXPECT_EQ(without_flat.students[0].name, "taught");
  const StudySpec without_a = SelectModels(spec, {"memory", "flat"}, 0);
  ASSERT_EQ(without_a.students.size(), 1U);
  EXPECT_EQ(without_a.students[0].name, "from_flat");
  EXPECT_TRUE(SelectModels(spec, {"a", "flat"}, 0).students.empty());
}

// A kind of fine-tune trains each student of a kind further, one per student; it goes with its
// student when a selection drops it.
TEST(StudySpecTest, StudiesFineTuneStudents) {
  const TemporaryFolder folder;
  const StudySpec spec = LoadStudySpec(WriteStudy(folder, R"(ppo:
  seeds: 3
  configs:
    a: {}
    memory: {set: {policy.recurrent_size: 8}}
students:
  taught: {teacher: a, start: memory}
fine_tunes:
  tuned: {student: taught, steps: 1000, set: {ppo.learning_rate: 2e-5, policy.log_std_init: -1}}
  plain: {student: taught, compare_to: tuned}
)"));
  ASSERT_EQ(spec.fine_tunes.size(), 2U);
  const FineTuneSpec& tuned = spec.fine_tunes[0];
  EXPECT_EQ(tuned.student, "taught");
  EXPECT_EQ(tuned.count, 3);  // taught's students, one per seed of a
  EXPECT_EQ(tuned.steps, 1000);
  EXPECT_EQ(tuned.overrides,
            (std::vector<std::string>{"ppo.learning_rate=2e-5", "policy.log_std_init=-1"}));
  EXPECT_EQ(spec.fine_tunes[1].steps, 0);  // the start configuration's
  const std::vector<SeededModel> models = spec.SeededModels();
  ASSERT_EQ(models.size(), 5U);  // 2 configurations, a student, 2 fine-tunes
  EXPECT_EQ(models[3].name, "tuned");
  EXPECT_EQ(models[3].seeds, 3);
  EXPECT_EQ(models[4].compare_to, "tuned");
  const StudySpec two_seeds = SelectModels(spec, {}, 2);
  ASSERT_EQ(two_seeds.fine_tunes.size(), 2U);
  EXPECT_EQ(two_seeds.fine_tunes[0].count, 2);
  EXPECT_TRUE(SelectModels(spec, {"memory"}, 0).fine_tunes.empty());  // no teacher, no student
}

// --only may name any model: it keeps what the named ones need and what is built from them alone.
TEST(StudySpecTest, SelectsAnyModelWithWhatItNeeds) {
  const TemporaryFolder folder;
  const StudySpec spec =
      LoadStudySpec(WriteStudy(folder, std::string(kRecurrentConfigs) + R"(ensembles:
  pair: {members: [a, memory, memory]}
students:
  taught: {teacher: pair, start: memory}
  from_flat: {teacher: flat, start: memory}
fine_tunes:
  tuned: {student: taught, steps: 1000}
  flat_tuned: {student: from_flat, steps: 1000}
)"));
  const auto names = [](const auto& specs) {
    std::vector<std::string> listed;
    for (const auto& s : specs) listed.push_back(s.name);
    return listed;
  };
  using Names = std::vector<std::string>;
  const StudySpec tuned = SelectModels(spec, {"tuned"}, 0);
  EXPECT_EQ(names(tuned.ppo_configs), (Names{"a", "memory"}));  // the teacher's members, the start
  EXPECT_EQ(names(tuned.ensembles), Names{"pair"});
  EXPECT_EQ(names(tuned.students), Names{"taught"});  // not from_flat, though built from memory
  EXPECT_EQ(names(tuned.fine_tunes), Names{"tuned"});
  EXPECT_EQ(tuned.fine_tunes[0].count, 2);  // pair's ensembles
  const StudySpec pair = SelectModels(spec, {"pair"}, 0);
  EXPECT_EQ(names(pair.ppo_configs), (Names{"a", "memory"}));
  EXPECT_TRUE(pair.students.empty());  // taught's start is needed by none of the named
  const StudySpec from_flat = SelectModels(spec, {"memory", "from_flat"}, 0);
  EXPECT_EQ(names(from_flat.ppo_configs), (Names{"memory", "flat"}));  // file order
  EXPECT_TRUE(from_flat.ensembles.empty());
  EXPECT_EQ(names(from_flat.students), Names{"from_flat"});
  EXPECT_EQ(names(from_flat.fine_tunes), Names{"flat_tuned"});  // built from a named student
  EXPECT_EQ(names(SelectModels(spec, {"flat_tuned"}, 2).fine_tunes), Names{"flat_tuned"});
  // One seed gives no pair (two runs of memory), so no taught and no tuned.
  EXPECT_NE(UserErrorMessage([&] {
              SelectModels(spec, {"tuned"}, 1);
            }).find("--only tuned: --seeds 1 gives none of it"),
            std::string::npos);
  EXPECT_NE(UserErrorMessage([&] {
              SelectModels(spec, {"taught", "nope"}, 0);
            })
                .find("--only nope: the study has no PPO configuration, ensemble, student or "
                      "fine-tune"),
            std::string::npos);
}

TEST(StudySpecTest, BadInputNamesTheFileAndKey) {
  const TemporaryFolder folder;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"ppo: {configs: {a: {extractor: cnn}}}", "ppo.configs.a.extractor"},
      {"ppo: {configs: {a: {extractor: vae-shallow}}}", "ppo.configs.a.vae"},
      {"ppo: {configs: {a: {extractor: vae-deep, vae: s}}}\nvaes: {s: {model: shallow}}",
       "ppo.configs.a.vae"},
      {"ppo: {seeds: 0, configs: {a: {}}}", "ppo.seeds"},
      {"ppo: {steps: 1.5, configs: {a: {}}}", "ppo.steps"},
      {"ppo: {configs: {a: {steps: 0}}}", "ppo.configs.a.steps"},
      {"ppo: {configs: {a: {locked: maybe}}}", "ppo.configs.a.locked"},
      {"ppo: {configs: {a: {}}}\nevaluation: {episodes: nan}", "evaluation.episodes"},
      {"ppo: {configs: {a: {}}}\nevaluation: {reference_agents: [missing.pt]}",
       "evaluation.reference_agents[0]"},
      {"ppo: {configs: {a: {}}}\nevaluation: {validation_episodes: -1}",
       "evaluation.validation_episodes"},
      {"ppo: {configs: {a: {}}}\nevaluation: {validation_episodes: 9, validation_seed: 1}",
       "evaluation.validation_seed"},
      {"ppo: {configs: {a: {}}}\nevaluation: {goal: {speed: 3}}", "evaluation.goal.speed"},
      {"ppo: {configs: {a: {}}}\nevaluation: {goal: {collision: 101}}",
       "evaluation.goal.collision"},
      {"ppo: {configs: {a: {}}}\nevaluation: {goal: {return: high}}", "evaluation.goal.return"},
      {"ppo: {configs: {a: {}}}\nevaluation: {goal: 3}", "evaluation.goal"},
      {"ppo: {configs: {a: {}}}\ncolour: red", "colour"},
      {"ppo: {configs: {'a/b': {}}}", "ppo.configs.a/b"},
      {"vaes: {s: {}}", "ppo"},
      {"ppo: {configs: {a: {}}}\nevaluation: {compare_to: b}", "evaluation.compare_to"},
      {"ppo: {configs: {a: {compare_to: b}}}", "ppo.configs.a.compare_to"},
      {"ppo: {configs: {a: {compare_to: a}}}", "ppo.configs.a.compare_to"},
      {"ppo: {configs: {a: {compare_to: [b]}}}", "ppo.configs.a.compare_to"},
      {"ppo: {configs: {a: {}}}\nvae_figures: often", "vae_figures"},
      {"ppo: {configs: {a: {}}}\nensembles: {e: {members: [a]}}", "ensembles.e.members"},
      {"ppo: {configs: {a: {}}}\nensembles: {e: {members: [a, b]}}", "ensembles.e.members[1]"},
      {"ppo: {seeds: 3, configs: {a: {}}}\nensembles: {e: {members: [a, a], count: 2}}",
       "ensembles.e.count"},
      {"ppo: {seeds: 1, configs: {a: {}}}\nensembles: {e: {members: [a, a]}}",
       "ensembles.e.members"},
      {"ppo: {configs: {a: {}}}\nensembles: {a: {members: [a, a]}}", "ensembles.a"},
      {"ppo: {configs: {a: {}}}\nensembles: {e: {members: [a, a], size: 2}}", "ensembles.e.size"},
      {"ppo: {seeds: 3, configs: {a: {}}}\nensembles: {e: {members: [a, a, a], near_within_m: 9}}",
       "ensembles.e.near_within_m"},
      {"ppo: {configs: {a: {}}}\nensembles: {e: {members: [a, a], near_within_m: 150}}",
       "ensembles.e.near_within_m"},
      {"ppo: {configs: {a: {}}}\nensembles: {e: {members: [a, a], near_within_m: near}}",
       "ensembles.e.near_within_m"},
      {"ppo: {configs: {a: {}}}\nensembles: {e: {members: [a, a], stall_pace_mps: 0.5}}",
       "ensembles.e.stall_pace_mps"},
      {"ppo: {configs: {a: {}}}\nensembles: {e: {members: [a, a], stall_steps: 100}}",
       "ensembles.e.stall_steps"},
      {"ppo: {configs: {a: {}}}\nensembles: {e: {members: [a, a], stall_pace_mps: 0.1, "
       "stall_steps: 0}}",
       "ensembles.e.stall_steps"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {start: a}}",
       "students.s.teacher"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: b, "
       "start: a}}",
       "students.s.teacher"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a}}",
       "students.s.start"},
      {"ppo: {configs: {a: {}}}\nstudents: {s: {teacher: a, start: a}}", "students.s.start"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {a: {teacher: a, "
       "start: a}}",
       "students.a"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a, options: {seed: 3}}}",
       "students.s.options.seed"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a, options: {--traps: 3}}}",
       "students.s.options.--traps"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a, options: [traps]}}",
       "students.s.options"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a, compare_to: s}}",
       "students.s.compare_to"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a, teachers: 2}}",
       "students.s.teachers"},
      {"ppo: {configs: {a: {}}}\nfine_tunes: {f: {student: a}}", "fine_tunes.f.student"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a}}\nfine_tunes: {f: {steps: 10}}",
       "fine_tunes.f.student"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a}}\nfine_tunes: {s: {student: s}}",
       "fine_tunes.s"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a}}\nfine_tunes: {f: {student: s, steps: 0}}",
       "fine_tunes.f.steps"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a}}\nfine_tunes: {f: {student: s, set: {policy.init: x.pt}}}",
       "fine_tunes.f.set.policy.init"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a}}\nfine_tunes: {f: {student: s, compare_to: f}}",
       "fine_tunes.f.compare_to"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a}}\nfine_tunes: {f: {student: s, compare_to: g}}",
       "fine_tunes.f.compare_to"},
      {"ppo: {configs: {a: {set: {policy.recurrent_size: 4}}}}\nstudents: {s: {teacher: a, "
       "start: a}}\nfine_tunes: {f: {student: s, rate: 2}}",
       "fine_tunes.f.rate"},
  };
  for (const auto& [text, key] : cases) {
    const std::string message = UserErrorMessage([&] { LoadStudySpec(WriteStudy(folder, text)); });
    EXPECT_NE(message.find("study.yaml: " + key), std::string::npos) << text << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace colav

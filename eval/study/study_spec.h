// A study file: the dataset, the VAEs, the PPO configurations times training seeds, and the
// evaluations of one experiment (interfaces.md, section "study"). Parsed and checked completely
// before any job starts; every problem is a one-line UserError naming the file and the key.
//
//   name: quickstart
//   dataset: {dataset.sim_scans: 10000}            # --set overrides of generate_dataset
//   vaes:
//     shallow: {model: shallow, seeds: 1, set: {vae.beta: 1.0}}
//   ppo:
//     seeds: 5
//     steps: 3000000
//     set: {}                                       # overrides of every configuration
//     configs:
//       shallow_locked: {extractor: vae-shallow, vae: shallow, locked: true}
//       baseline: {extractor: baseline}
//       shallow_log: {extractor: vae-shallow, vae: shallow, compare_to: shallow_locked}
//   ensembles:                                      # agents averaging several runs' actions
//     two_shallow: {members: [shallow_locked, shallow_locked], count: 2}
//   students:                                       # teachers distilled into one network each
//     distilled: {teacher: two_shallow, start: shallow_memory, options: {traps: 8}}
//   fine_tunes:                                     # students trained further by PPO
//     distilled_ppo: {student: distilled, steps: 3000000, set: {ppo.learning_rate: 2e-5}}
//   evaluation:
//     episodes: 1000                                # scenarios of the study's own table
//     seed: 1
//     paper_episodes: 100                           # the paper's table (master seed 0); 0: none
//     validation_episodes: 1000                     # scenarios to choose on, apart from the
//     validation_seed: 2                            # test's (another master seed); 0 episodes:
//                                                   # none (the default)
//     goal: {progress: 97, cross_track_error: 17, collision: 3}  # bounds the report measures
//                                                   # each model against; with validation
//                                                   # scenarios, the model they choose
//     reference_agents: [../shared/reference-agents/shallow_locked_3m.pt]
//     paper_results: paper_results.yaml              # the paper's table, printed beside ours
//     compare_to: baseline                          # the configuration the others are compared
//     with
//   vae_figures: true                               # the paper's VAE figures (vae_figures)
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "eval/stall_rule.h"

namespace colav {

/// "key=value" overrides passed to a program with --set, in file order.
using Overrides = std::vector<std::string>;

/// The number the last assignment of `key` in `chain` (overrides in the order a program reads
/// them) spells: NaN when its value is not one number, `fallback` when none assigns `key`.
double LastSetting(std::initializer_list<const Overrides*> chain, const std::string& key,
                   double fallback);

struct VaeSpec {
  std::string name;
  std::string model = "shallow";  ///< shallow | deep
  int seeds = 1;
  Overrides overrides;
};

struct PpoConfigSpec {
  std::string name;
  std::string extractor = "baseline";  ///< baseline | vae-shallow | vae-deep
  std::string vae;                     ///< name of the VAE whose encoders it uses
  bool locked = true;
  Overrides overrides;  ///< after the study-wide ones
  /// Environment steps of each run; 0: the study's ppo.steps (longer training, paired with it).
  std::int64_t steps = 0;
  /// The configuration or ensemble this one is compared with; empty: evaluation.compare_to (so a
  /// study can hold variants of several recipes, each compared with its own).
  std::string compare_to{};
};

/// A kind of ensemble: agents acting with the mean of several of the study's runs' actions
/// (eval/policy_ensemble.h), built once the runs exist and evaluated with them. Ensemble k of the
/// kind takes seed k + j * count of the configuration listed for the j-th time in `members`
/// (j = 0, 1, ...), so no two ensembles of a kind share a run and they stand for `count` training
/// seeds: {members: [best, best, memory], count: 5} takes best's seeds k and k + 5 and memory's
/// seed k.
struct EnsembleSpec {
  std::string name;
  std::vector<std::string> members;  ///< PPO configurations; one listed twice gives two runs
  int count = 1;                     ///< ensembles of this kind
  /// The first steers while an obstacle is within this many metres, the second otherwise
  /// (EnsembleRule, eval/policy_ensemble.h; two members, more with a stall rule); absent: the mean
  /// of every member's action.
  std::optional<double> near_within_m;
  /// Member k (k >= 1) steers from the vessel's k-th stall on, the last to the episode's end.
  std::optional<StallRule> stall;
  /// `count` was written in the study file; otherwise it is the most the training seeds give
  /// (MaxCount), also when study --seeds changes them.
  bool count_given = false;

  /// The training seed of member `member` (an index into members) in ensemble `k`.
  int MemberSeed(std::size_t member, int k) const;
  /// The most ensembles of these members that `seeds` runs per configuration give.
  int MaxCount(int seeds) const;
};

/// A kind of student: each of a teacher's seeds distilled by DAgger into one recurrent network
/// (scripts/distill_policy.py, run as build/bin/distill_policy). Student k imitates the teacher's
/// seed k (ensemble k of an ensemble kind, run k of a configuration) and starts from a run of the
/// recurrent configuration `start`: the one ensemble k takes when `start` is among its members,
/// else seed k. Its distillation seed is k.
struct StudentSpec {
  std::string name;
  std::string teacher;  ///< an ensemble kind or a PPO configuration of the study
  std::string start;    ///< a recurrent PPO configuration (policy.recurrent_size > 0)
  /// distill_policy's options, as "--name value" pairs in file order (after the study's
  /// "--threads 1", which they may override).
  std::vector<std::string> options;
  int count = 1;             ///< students of this kind: the teacher's seeds
  std::string compare_to{};  ///< as PpoConfigSpec::compare_to
};

/// A kind of fine-tuned student: each student of a kind trained further by PPO (train_ppo with
/// policy.init = the student's policy). Fine-tune k starts from student k with the settings of the
/// run that student started from (its configuration's, at its training seed:
/// StudySpec::StartSeed), then `overrides`, for `steps` environment steps.
struct FineTuneSpec {
  std::string name;
  std::string student;       ///< a kind of student of the study
  Overrides overrides;       ///< after the start configuration's
  std::int64_t steps = 0;    ///< 0: the start configuration's steps
  int count = 1;             ///< fine-tunes of this kind: the student's count
  std::string compare_to{};  ///< as PpoConfigSpec::compare_to
};

/// A model of several seeds in the report: a PPO configuration (its training seeds), an ensemble
/// kind (its ensembles), a kind of student (its students) or of fine-tuned student; its models
/// are named SeedModelName(name, k), k < seeds.
struct SeededModel {
  std::string name;
  int seeds = 0;
  std::string compare_to{};  ///< a configuration's own (PpoConfigSpec::compare_to); empty: none
};

struct EvaluationSpec {
  int episodes = 1000;
  std::uint64_t seed = 1;
  int paper_episodes = 100;  ///< on master seed 0, for the paper's table; 0 = none
  /// Scenarios to choose settings on without touching the test's (its own table in the report,
  /// eval/validation/); 0 = none. Their master seed must differ from `seed`.
  int validation_episodes = 0;
  std::uint64_t validation_seed = 2;
  /// A bound per metric (StudyMetrics' names, the report's units): at least it where higher is
  /// better, at most it otherwise. The report measures how far each model's means fall short of
  /// them, and with validation scenarios names the model those choose (goal_shortfall.h).
  /// Empty = none.
  std::map<std::string, double> goal;
  std::vector<std::filesystem::path> reference_agents;
  std::filesystem::path paper_results;  ///< the paper's table (YAML); empty = none
  /// The configuration every other one is compared with (probability of improvement), unless
  /// it names its own (PpoConfigSpec::compare_to).
  std::string compare_to = "baseline";
};

struct StudySpec {
  std::string name;
  Overrides dataset_overrides;
  std::vector<VaeSpec> vaes;
  int ppo_seeds = 5;
  std::int64_t ppo_steps = 3'000'000;
  Overrides ppo_overrides;
  std::vector<PpoConfigSpec> ppo_configs;
  std::vector<EnsembleSpec> ensembles;
  std::vector<StudentSpec> students;
  std::vector<FineTuneSpec> fine_tunes;
  EvaluationSpec evaluation;
  /// Also draw the paper's VAE figures (padding comparison, latent densities) on the study's
  /// dataset: eight small VAEs, a few minutes.
  bool vae_figures = false;

  /// The environment steps of `config`'s runs: its own, else the study's.
  std::int64_t StepsOf(const PpoConfigSpec& config) const {
    return config.steps > 0 ? config.steps : ppo_steps;
  }
  /// The environment steps of `fine_tune`'s runs: its own, else its students' start
  /// configuration's.
  std::int64_t StepsOf(const FineTuneSpec& fine_tune) const {
    return fine_tune.steps > 0 ? fine_tune.steps
                               : StepsOf(*FindConfig(FindStudent(fine_tune.student)->start));
  }
  /// The PPO configurations, then the ensemble kinds, the kinds of student and of fine-tuned
  /// student, in file order.
  std::vector<SeededModel> SeededModels() const;
  /// Whether the study has a PPO configuration, ensemble kind, kind of student or of fine-tune
  /// named `name`.
  bool HasModel(const std::string& name) const;
  /// The PPO configuration named `name`, if there is one.
  const PpoConfigSpec* FindConfig(const std::string& name) const;
  /// The ensemble kind named `name`, if there is one.
  const EnsembleSpec* FindEnsemble(const std::string& name) const;
  /// The kind of student named `name`, if there is one.
  const StudentSpec* FindStudent(const std::string& name) const;
  /// The seeds of a teacher: an ensemble kind's count, a configuration's training seeds; 0 when
  /// the study has neither of that name.
  int TeacherSeeds(const std::string& teacher) const;
  /// The training seed of the run of `student.start` that student k starts from (StudentSpec).
  int StartSeed(const StudentSpec& student, int k) const;
};

/// The study of `path`; relative reference-agent paths are taken from the study file's folder.
StudySpec LoadStudySpec(const std::filesystem::path& path);

/// The study restricted to the models `only` names (PPO configurations, ensemble kinds, kinds of
/// student or of fine-tune), the kinds built from the named ones alone (an ensemble all of whose
/// members it names, a student whose teacher and start it names or builds, a fine-tune of a
/// student it keeps) and what all of these are built from (members, teachers, starts, students,
/// VAEs), without VAE figures; all of it when `only` is empty. With `seeds` > 0, that many
/// training seeds (and as many ensembles of each kind as they give, none when they give none; a
/// student per teacher seed, a fine-tune per student). A name the study does not have, or has
/// none of with `seeds`, is a UserError.
StudySpec SelectModels(StudySpec spec, const std::vector<std::string>& only, int seeds);

}  // namespace colav

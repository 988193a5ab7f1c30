// The jobs of a study and their order: dataset -> VAEs -> PPO runs -> ensembles -> students ->
// fine-tunes -> evaluations. Each job is one run of a project program into its own output folder
// under the study folder
// (interfaces.md, section "study"); a job is complete when its program's last output exists, and
// resumable when its program left a checkpoint.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "eval/study/study_spec.h"

namespace colav {

struct StudyJob {
  std::string id;       ///< "ppo/baseline/seed_0": also its folder under the study folder
  std::string program;  ///< a program of build/bin
  std::vector<std::string> args;
  /// Arguments that continue an interrupted run (empty: rerun `args`, the program resumes).
  std::vector<std::string> resume_args;
  /// Exists once the job has finished (a JSON summary with "finished": false does not count).
  std::filesystem::path complete_marker;
  std::filesystem::path resume_marker;    ///< exists while an interrupted run can be continued
  std::vector<std::size_t> dependencies;  ///< indices of jobs that must finish first
  double estimated_s = 1.0;               ///< for the ETA and to start long jobs first
  /// Evaluations: complete only when their summary lists exactly these models (a study that gained
  /// configurations evaluates again).
  std::vector<std::string> expected_models;
  /// Checked with --print-config before the study starts (one seed stands for its siblings).
  bool check_configuration = true;
  /// The settings a finished run recorded, compared with --print-config's (recorded_settings.h);
  /// empty: config.yaml beside the complete marker.
  std::filesystem::path recorded_settings{};
};

/// Models evaluated together, paired, on one scenario set (one evaluate run).
struct EvaluationGroup {
  std::string scenario_set;         ///< "study", "paper" or "validation": folder eval/<set>
  std::vector<std::string> models;  ///< model names, e.g. "baseline.seed_0", "ref.baseline_3m"
  std::vector<std::filesystem::path> policies;
  std::vector<int> networks;  ///< the networks each model runs: an ensemble's members, else 1
  int episodes = 0;
  std::uint64_t seed = 0;
};

/// The job's id as one file name ("ppo/baseline/seed_0" -> "ppo_baseline_seed_0"): its log, its
/// claims.
std::string JobFileStem(const std::string& id);

/// "figures/vae": vae_figures' folder (padding_comparison.png, latent_kde.png) when the study
/// draws them, relative to the study's output folder.
std::filesystem::path VaeFiguresFolder();

/// "figures/training_<config>.png": the training curves of a configuration's seeds, relative to the
/// study's output folder.
std::filesystem::path TrainingFigurePath(const std::string& config);

/// "ppo/<config>/seed_<k>": a PPO run's folder under the study folder, and its job's id.
std::filesystem::path RunFolder(const std::string& config, int seed);

/// "students/<student>/seed_<k>": a student's folder under the study folder, and its job's id.
std::filesystem::path StudentFolder(const std::string& student, int k);

/// "<StudentFolder>/policy.pt.json": distill_policy's summary of the student's run (its settings,
/// each iteration, whether it finished), relative to the study's output folder.
std::filesystem::path StudentSummaryFile(const std::string& student, int k);

/// "fine_tunes/<fine_tune>/seed_<k>": a fine-tuned student's train_ppo run folder under the study
/// folder, and its job's id.
std::filesystem::path FineTuneFolder(const std::string& fine_tune, int k);

/// The train_ppo runs of one PPO configuration or one kind of fine-tuned student: their folders
/// under the study folder, seed k's k-th.
struct PpoRunKind {
  std::string name;
  std::vector<std::filesystem::path> folders;
};

/// The study's train_ppo runs: each configuration's, then each kind of fine-tune's.
std::vector<PpoRunKind> PpoRunKinds(const StudySpec& spec);

/// "<config>.seed_<k>": the model name of a PPO run in evaluations.
std::string SeedModelName(const std::string& config, int seed);

/// The evaluation groups of a study: every PPO run and reference agent on the study's scenarios,
/// the same on the paper's scenarios when paper_episodes > 0 and on the validation scenarios when
/// validation_episodes > 0. Each policy runs under the observation settings it records or its
/// sidecar gives (evaluate), so models trained under different settings are still compared
/// paired.
std::vector<EvaluationGroup> EvaluationGroups(const StudySpec& spec,
                                              const std::filesystem::path& out);

/// Every job of the study with outputs in `out`, dependencies before dependants.
std::vector<StudyJob> BuildJobGraph(const StudySpec& spec, const std::filesystem::path& out);

}  // namespace colav

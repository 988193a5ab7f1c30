#include "eval/study/job_graph.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <initializer_list>
#include <map>
#include <string_view>
#include <utility>

namespace colav {
namespace {

// Rough costs on the 2-core reference machine, for the ETA and the start order only.
// Measured: 35 runs of `best` and its one-setting variants at 4 passes (15M steps, two runs at a
// time, studies/best_knobs.yaml, best_std.yaml, best_timeouts.yaml) took 300-391 s, median 305.
constexpr double kPpoStepsPerSecond = 45'000.0;
// A PPO run's update share of its time at the paper's 4 passes per rollout, which scales with the
// passes (ppo.n_epochs), and a memory's (policy.recurrent_size > 0) factor on the whole run.
// Measured on `best` (15M steps, two runs at a time): 226, 303, 408 and 600 s at 2, 4, 6 and 10
// passes, a line of 47 s a pass from 124 s (studies/best_knobs.yaml, docs/results/learner.md
// "The learner's last untouched"); with a memory, 520 s at 4 (README "Speed").
constexpr double kPpoPaperPasses = 4.0;
constexpr double kPpoUpdateShareAtPaperPasses = 0.6;
constexpr double kPpoMemoryFactor = 1.75;
constexpr double kVaeSecondsPerSeed = 12.0;
// An evaluation's seconds per test episode of a model running N networks: a + b N, for an
// evaluation beside another job (two at a time, as the PPO figures). Measured on studies'
// evaluations of 1,000 scenarios side by side (critic_near_memory_far at 10 seeds, reusing the
// first 5): 15,000 episodes of single networks (feed-forward and memories) in 203-208 s, 20,000
// of three-member ensembles in 440-447 s. One evaluation alone on both cores runs about twice as
// fast (43,000 episodes of 43 models in 443 s).
constexpr double kEvaluationSecondsPerEpisode = 0.0095;
constexpr double kEvaluationSecondsPerNetworkEpisode = 0.0043;
constexpr double kDatasetSeconds = 2.0;
constexpr double kFigureSeconds = 2.0;
constexpr double kVaeFiguresSeconds = 150.0;
constexpr double kEnsembleSeconds = 2.0;
constexpr double kStudentSeconds = 600.0;  // distill_policy's defaults, two at a time
// distill_policy's options its cost is proportional to (the steps it plays and trains on), with
// their defaults.
constexpr std::array<std::pair<std::string_view, double>, 3> kStudentCostOptions = {
    {{"--iterations", 8.0}, {"--worlds", 32.0}, {"--steps", 2048.0}}};
// distill_policy's threads unless a student's options say otherwise: the same file whatever the
// machine (its results depend on the thread count), and two students keep two cores busy.
constexpr int kStudentThreads = 1;

// The policy file of training seed `seed` of `config`.
std::filesystem::path RunPolicy(const std::filesystem::path& out, const std::string& config,
                                int seed) {
  return out / RunFolder(config, seed) / "policy.pt";
}

// The policy file of ensemble `k` of the kind `ensemble`.
std::filesystem::path EnsemblePolicyFile(const std::filesystem::path& out,
                                         const std::string& ensemble, int k) {
  return out / "ensembles" / ensemble / ("seed_" + std::to_string(k)) / "policy.pt";
}

// The policy file of student `k` of the kind `student`.
std::filesystem::path StudentPolicyFile(const std::filesystem::path& out,
                                        const std::string& student, int k) {
  return out / StudentFolder(student, k) / "policy.pt";
}

// The policy file of fine-tune `k` of the kind `fine_tune`.
std::filesystem::path FineTunePolicyFile(const std::filesystem::path& out,
                                         const std::string& fine_tune, int k) {
  return out / FineTuneFolder(fine_tune, k) / "policy.pt";
}

// The policy file of seed `k` of the ensemble kind or configuration `teacher`.
std::filesystem::path TeacherPolicyFile(const StudySpec& spec, const std::filesystem::path& out,
                                        const std::string& teacher, int k) {
  return spec.FindEnsemble(teacher) ? EnsemblePolicyFile(out, teacher, k)
                                    : RunPolicy(out, teacher, k);
}

// A student's rough cost: kStudentSeconds scaled by its options (pairs of "--name value") that
// kStudentCostOptions names. A value that is not a positive number scales nothing: the student's
// --print-config check refuses it before any job runs.
double StudentSeconds(const std::vector<std::string>& options) {
  double seconds = kStudentSeconds;
  for (std::size_t i = 0; i + 1 < options.size(); i += 2) {
    for (const auto& [name, default_value] : kStudentCostOptions) {
      if (options[i] != name) continue;
      char* end = nullptr;
      const double value = std::strtod(options[i + 1].c_str(), &end);
      if (*end == '\0' && value > 0.0) seconds *= value / default_value;
    }
  }
  return seconds;
}

// A PPO run's rough cost from its steps and the passes per rollout and memory its settings
// (`chain`, in the order train_ppo reads them) give it. A value that is not a positive number
// scales nothing: train_ppo refuses it before any job runs.
double PpoRunSeconds(std::int64_t steps, std::initializer_list<const Overrides*> chain) {
  const double passes = LastSetting(chain, "ppo.n_epochs", kPpoPaperPasses);
  const double pass_scale = passes > 0.0 ? passes / kPpoPaperPasses : 1.0;  // false for NaN
  const double memory =
      LastSetting(chain, "policy.recurrent_size", 0.0) > 0.0 ? kPpoMemoryFactor : 1.0;
  const double share = kPpoUpdateShareAtPaperPasses;
  return static_cast<double>(steps) / kPpoStepsPerSecond * memory *
         (1.0 - share + share * pass_scale);
}

void AppendOverrides(std::vector<std::string>& args, const Overrides& overrides) {
  for (const std::string& assignment : overrides) {
    args.emplace_back("--set");
    args.push_back(assignment);
  }
}

// Every model of the study on one scenario set, in one paired evaluation: each policy runs under
// the observation settings it records (the reference agents': their sidecar files).
EvaluationGroup GroupOnScenarios(const StudySpec& spec, const std::filesystem::path& out,
                                 const std::string& scenarios, int episodes, std::uint64_t seed) {
  EvaluationGroup group{scenarios, {}, {}, {}, episodes, seed};
  const auto add = [&group](std::string model, std::filesystem::path policy, int networks) {
    group.models.push_back(std::move(model));
    group.policies.push_back(std::move(policy));
    group.networks.push_back(networks);
  };
  for (const PpoConfigSpec& config : spec.ppo_configs) {
    for (int k = 0; k < spec.ppo_seeds; ++k) {
      add(SeedModelName(config.name, k), RunPolicy(out, config.name, k), 1);
    }
  }
  for (const EnsembleSpec& ensemble : spec.ensembles) {
    for (int k = 0; k < ensemble.count; ++k) {
      add(SeedModelName(ensemble.name, k), EnsemblePolicyFile(out, ensemble.name, k),
          static_cast<int>(ensemble.members.size()));
    }
  }
  for (const StudentSpec& student : spec.students) {
    for (int k = 0; k < student.count; ++k) {
      add(SeedModelName(student.name, k), StudentPolicyFile(out, student.name, k), 1);
    }
  }
  for (const FineTuneSpec& fine_tune : spec.fine_tunes) {
    for (int k = 0; k < fine_tune.count; ++k) {
      add(SeedModelName(fine_tune.name, k), FineTunePolicyFile(out, fine_tune.name, k), 1);
    }
  }
  for (const std::filesystem::path& agent : spec.evaluation.reference_agents) {
    add("ref." + agent.stem().string(), agent, 1);
  }
  return group;
}

// The seconds an evaluation of `group` takes beside another job.
double EvaluationSeconds(const EvaluationGroup& group) {
  double per_scenario_s = 0.0;
  for (const int networks : group.networks) {
    per_scenario_s += kEvaluationSecondsPerEpisode + kEvaluationSecondsPerNetworkEpisode * networks;
  }
  return per_scenario_s * group.episodes;
}

// A job running `program` with `args`, complete once `complete_marker` exists.
StudyJob NewJob(std::string id, std::string program, std::vector<std::string> args,
                std::filesystem::path complete_marker, double estimated_s) {
  StudyJob job;
  job.id = std::move(id);
  job.program = std::move(program);
  job.args = std::move(args);
  job.complete_marker = std::move(complete_marker);
  job.estimated_s = estimated_s;
  return job;
}

std::size_t AddJob(std::vector<StudyJob>& jobs, StudyJob job) {
  jobs.push_back(std::move(job));
  return jobs.size() - 1;
}

// One plot_training job per kind of PPO run, drawing the training curves of all its seeds.
void AddTrainingFigureJobs(std::vector<StudyJob>& jobs, const StudySpec& spec,
                           const std::filesystem::path& out,
                           const std::map<std::string, std::size_t>& policy_jobs) {
  for (const PpoRunKind& kind : PpoRunKinds(spec)) {
    const std::filesystem::path png = out / TrainingFigurePath(kind.name);
    StudyJob job = NewJob("figures/training/" + kind.name, "plot_training",
                          {"--out", png.string(), "--title",
                           fmt::format("Training of {}, {} seeds", kind.name, kind.folders.size())},
                          png, kFigureSeconds);
    job.check_configuration = false;  // every argument comes from the study, none from the user
    for (std::size_t k = 0; k < kind.folders.size(); ++k) {
      const std::filesystem::path run = out / kind.folders[k];
      job.args.insert(job.args.end(), {"--run", fmt::format("seed_{}={}", k, run.string())});
      job.dependencies.push_back(policy_jobs.at((run / "policy.pt").string()));
    }
    AddJob(jobs, job);
  }
}

// A train_ppo job with `config`'s settings at training seed `seed` for `steps` environment
// steps, writing the run folder `id` under `out`; it depends on the VAE job of its encoder.
StudyJob PpoRunJob(const StudySpec& spec, const PpoConfigSpec& config, int seed, std::int64_t steps,
                   const std::filesystem::path& out, const std::string& id,
                   const std::map<std::string, std::size_t>& vae_jobs) {
  const std::filesystem::path dir = out / id;
  StudyJob job = NewJob(id, "train_ppo", {"--extractor", config.extractor}, dir / "summary.json",
                        PpoRunSeconds(steps, {&spec.ppo_overrides, &config.overrides}));
  job.resume_args = {"--resume", dir.string()};
  job.resume_marker = dir / "training_state.pt";
  if (config.extractor != "baseline") {
    const VaeSpec& vae = *std::find_if(spec.vaes.begin(), spec.vaes.end(),
                                       [&](const VaeSpec& v) { return v.name == config.vae; });
    // PPO seed k uses VAE seed k (cycling when the VAE has fewer seeds).
    const std::filesystem::path encoder =
        out / "vae" / vae.name / ("seed_" + std::to_string(seed % vae.seeds)) / "encoder.pt";
    job.args.insert(job.args.end(),
                    {"--encoder", encoder.string(), config.locked ? "--locked" : "--unlocked"});
    job.dependencies.push_back(vae_jobs.at(config.vae));
  }
  job.args.insert(job.args.end(), {"--steps", std::to_string(steps), "--seed", std::to_string(seed),
                                   "--out", dir.string()});
  AppendOverrides(job.args, spec.ppo_overrides);
  AppendOverrides(job.args, config.overrides);
  return job;
}

// One train_ppo job per fine-tuned student, after the student (study_spec.h, FineTuneSpec).
void AddFineTuneJobs(std::vector<StudyJob>& jobs, const StudySpec& spec,
                     const std::filesystem::path& out,
                     const std::map<std::string, std::size_t>& vae_jobs,
                     std::map<std::string, std::size_t>& policy_jobs) {
  for (const FineTuneSpec& fine_tune : spec.fine_tunes) {
    const StudentSpec& student = *spec.FindStudent(fine_tune.student);
    const PpoConfigSpec& start = *spec.FindConfig(student.start);
    for (int k = 0; k < fine_tune.count; ++k) {
      const std::filesystem::path student_policy = StudentPolicyFile(out, student.name, k);
      StudyJob job = PpoRunJob(spec, start, spec.StartSeed(student, k), spec.StepsOf(fine_tune),
                               out, FineTuneFolder(fine_tune.name, k).string(), vae_jobs);
      AppendOverrides(job.args, {"policy.init=" + student_policy.string()});
      AppendOverrides(job.args, fine_tune.overrides);
      job.estimated_s = PpoRunSeconds(
          spec.StepsOf(fine_tune), {&spec.ppo_overrides, &start.overrides, &fine_tune.overrides});
      job.check_configuration = k == 0;
      job.dependencies.push_back(policy_jobs.at(student_policy.string()));
      policy_jobs[FineTunePolicyFile(out, fine_tune.name, k).string()] = AddJob(jobs, job);
    }
  }
}

// One ensemble_policy job per ensemble, after the runs it averages (study_spec.h, EnsembleSpec).
void AddEnsembleJobs(std::vector<StudyJob>& jobs, const StudySpec& spec,
                     const std::filesystem::path& out,
                     std::map<std::string, std::size_t>& policy_jobs) {
  for (const EnsembleSpec& ensemble : spec.ensembles) {
    for (int k = 0; k < ensemble.count; ++k) {
      const std::filesystem::path policy = EnsemblePolicyFile(out, ensemble.name, k);
      StudyJob job =
          NewJob("ensembles/" + ensemble.name + "/seed_" + std::to_string(k), "ensemble_policy",
                 {"--out", policy.string()}, policy, kEnsembleSeconds);
      job.check_configuration = false;  // every argument comes from the study, none from the user
      if (ensemble.near_within_m) {
        job.args.insert(job.args.end(),
                        {"--near-within", fmt::format("{}", *ensemble.near_within_m)});
      }
      if (ensemble.stall) {
        job.args.insert(job.args.end(),
                        {"--stall-pace", fmt::format("{}", ensemble.stall->pace_mps),
                         "--stall-steps", std::to_string(ensemble.stall->steps)});
      }
      for (std::size_t i = 0; i < ensemble.members.size(); ++i) {
        const std::filesystem::path member =
            RunPolicy(out, ensemble.members[i], ensemble.MemberSeed(i, k));
        job.args.push_back(member.string());
        job.dependencies.push_back(policy_jobs.at(member.string()));
      }
      policy_jobs[policy.string()] = AddJob(jobs, job);
    }
  }
}

// One distill_policy job per student, after its teacher and the run it starts from
// (study_spec.h, StudentSpec). Finished when its summary says so (STUDENT.pt.json, which also
// records its settings); continued from its state (STUDENT.pt.state) when stopped.
void AddStudentJobs(std::vector<StudyJob>& jobs, const StudySpec& spec,
                    const std::filesystem::path& out,
                    std::map<std::string, std::size_t>& policy_jobs) {
  for (const StudentSpec& student : spec.students) {
    for (int k = 0; k < student.count; ++k) {
      const std::filesystem::path policy = StudentPolicyFile(out, student.name, k);
      const std::filesystem::path teacher = TeacherPolicyFile(spec, out, student.teacher, k);
      const std::filesystem::path start = RunPolicy(out, student.start, spec.StartSeed(student, k));
      StudyJob job =
          NewJob(StudentFolder(student.name, k).string(), "distill_policy",
                 {teacher.string(), start.string(), "--out", policy.string(), "--seed",
                  std::to_string(k), "--threads", std::to_string(kStudentThreads)},
                 out / StudentSummaryFile(student.name, k), StudentSeconds(student.options));
      job.args.insert(job.args.end(), student.options.begin(), student.options.end());
      job.resume_args = job.args;
      job.resume_args.emplace_back("--resume");
      job.resume_marker = policy.string() + ".state";
      job.recorded_settings = job.complete_marker;
      job.check_configuration = k == 0;
      job.dependencies = {policy_jobs.at(teacher.string()), policy_jobs.at(start.string())};
      policy_jobs[policy.string()] = AddJob(jobs, job);
    }
  }
}

}  // namespace

std::string JobFileStem(const std::string& id) {
  std::string stem = id;
  std::replace(stem.begin(), stem.end(), '/', '_');
  return stem;
}

std::filesystem::path VaeFiguresFolder() { return std::filesystem::path("figures") / "vae"; }

std::filesystem::path TrainingFigurePath(const std::string& config) {
  return std::filesystem::path("figures") / ("training_" + config + ".png");
}

std::filesystem::path RunFolder(const std::string& config, int seed) {
  return std::filesystem::path("ppo") / config / ("seed_" + std::to_string(seed));
}

std::filesystem::path StudentFolder(const std::string& student, int k) {
  return std::filesystem::path("students") / student / ("seed_" + std::to_string(k));
}

std::filesystem::path StudentSummaryFile(const std::string& student, int k) {
  return StudentFolder(student, k) / "policy.pt.json";
}

std::filesystem::path FineTuneFolder(const std::string& fine_tune, int k) {
  return std::filesystem::path("fine_tunes") / fine_tune / ("seed_" + std::to_string(k));
}

std::vector<PpoRunKind> PpoRunKinds(const StudySpec& spec) {
  std::vector<PpoRunKind> kinds;
  for (const PpoConfigSpec& config : spec.ppo_configs) {
    PpoRunKind& kind = kinds.emplace_back(PpoRunKind{config.name, {}});
    for (int k = 0; k < spec.ppo_seeds; ++k) kind.folders.push_back(RunFolder(config.name, k));
  }
  for (const FineTuneSpec& fine_tune : spec.fine_tunes) {
    PpoRunKind& kind = kinds.emplace_back(PpoRunKind{fine_tune.name, {}});
    for (int k = 0; k < fine_tune.count; ++k) {
      kind.folders.push_back(FineTuneFolder(fine_tune.name, k));
    }
  }
  return kinds;
}

std::string SeedModelName(const std::string& config, int seed) {
  return config + ".seed_" + std::to_string(seed);
}

std::vector<EvaluationGroup> EvaluationGroups(const StudySpec& spec,
                                              const std::filesystem::path& out) {
  std::vector<EvaluationGroup> groups = {
      GroupOnScenarios(spec, out, "study", spec.evaluation.episodes, spec.evaluation.seed)};
  if (spec.evaluation.paper_episodes > 0) {
    groups.push_back(GroupOnScenarios(spec, out, "paper", spec.evaluation.paper_episodes, 0));
  }
  if (spec.evaluation.validation_episodes > 0) {
    groups.push_back(GroupOnScenarios(spec, out, "validation", spec.evaluation.validation_episodes,
                                      spec.evaluation.validation_seed));
  }
  return groups;
}

std::vector<StudyJob> BuildJobGraph(const StudySpec& spec, const std::filesystem::path& out) {
  std::vector<StudyJob> jobs;
  const std::filesystem::path data = out / "data" / "scans.h5";
  StudyJob dataset =
      NewJob("data", "generate_dataset", {"--out", data.string()}, data, kDatasetSeconds);
  AppendOverrides(dataset.args, spec.dataset_overrides);
  const std::size_t dataset_index = AddJob(jobs, dataset);

  if (spec.vae_figures) {
    const std::filesystem::path dir = out / VaeFiguresFolder();
    StudyJob figures =
        NewJob("figures/vae", "vae_figures", {"--data", data.string(), "--out", dir.string()},
               dir / "latent_kde.png", kVaeFiguresSeconds);
    figures.dependencies = {dataset_index};
    AddJob(jobs, figures);
  }
  std::map<std::string, std::size_t> vae_jobs;
  for (const VaeSpec& vae : spec.vaes) {
    const std::filesystem::path dir = out / "vae" / vae.name;
    StudyJob job = NewJob("vae/" + vae.name, "train_vae",
                          {"--data", data.string(), "--model", vae.model, "--seeds",
                           std::to_string(vae.seeds), "--out", dir.string()},
                          dir / "summary.json", kVaeSecondsPerSeed * vae.seeds);
    job.dependencies = {dataset_index};
    AppendOverrides(job.args, vae.overrides);
    vae_jobs[vae.name] = AddJob(jobs, job);
  }

  std::map<std::string, std::size_t> policy_jobs;  // policy.pt path -> the job that writes it
  for (const PpoConfigSpec& config : spec.ppo_configs) {
    for (int k = 0; k < spec.ppo_seeds; ++k) {
      StudyJob job = PpoRunJob(spec, config, k, spec.StepsOf(config), out,
                               RunFolder(config.name, k).string(), vae_jobs);
      job.check_configuration = k == 0;
      policy_jobs[RunPolicy(out, config.name, k).string()] = AddJob(jobs, job);
    }
  }

  AddEnsembleJobs(jobs, spec, out, policy_jobs);
  AddStudentJobs(jobs, spec, out, policy_jobs);
  AddFineTuneJobs(jobs, spec, out, vae_jobs, policy_jobs);
  AddTrainingFigureJobs(jobs, spec, out, policy_jobs);
  for (const EvaluationGroup& group : EvaluationGroups(spec, out)) {
    const std::filesystem::path dir = out / "eval" / group.scenario_set;
    StudyJob job = NewJob("eval/" + group.scenario_set, "evaluate", {}, dir / "summary.json",
                          EvaluationSeconds(group));
    for (std::size_t m = 0; m < group.models.size(); ++m) {
      const auto writer = policy_jobs.find(group.policies[m].string());
      if (writer != policy_jobs.end()) job.dependencies.push_back(writer->second);
      job.args.insert(job.args.end(),
                      {"--policy", group.policies[m].string(), "--name", group.models[m]});
    }
    job.expected_models = group.models;
    job.args.insert(job.args.end(),
                    {"--episodes", std::to_string(group.episodes), "--seed",
                     std::to_string(group.seed), "--trajectories", "0", "--out", dir.string(),
                     // A rerun (models added to the study) replaces the previous evaluation,
                     // taking its episodes of the models whose policy files are unchanged.
                     "--overwrite", "--reuse", dir.string()});
    AddJob(jobs, job);
  }
  return jobs;
}

}  // namespace colav

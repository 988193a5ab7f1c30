#include "eval/study/job_graph.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <map>

#include "src/yaml_file.h"

namespace colav {
namespace {

// Rough costs on the 2-core reference machine, for the ETA and the start order only.
constexpr double kPpoStepsPerSecond = 35'000.0;
constexpr double kVaeSecondsPerSeed = 12.0;
constexpr double kEvaluationEpisodesPerSecond = 200.0;
constexpr double kDatasetSeconds = 2.0;

void AppendOverrides(std::vector<std::string>& args, const Overrides& overrides) {
  for (const std::string& assignment : overrides) {
    args.emplace_back("--set");
    args.push_back(assignment);
  }
}

// The env.* overrides among `overrides`, in order (they decide an evaluation's environment).
Overrides EnvironmentOverrides(const Overrides& overrides) {
  Overrides env;
  for (const std::string& assignment : overrides) {
    if (assignment.rfind("env.", 0) == 0) env.push_back(assignment);
  }
  return env;
}

// The env settings of a reference agent's sidecar "<policy>.yaml" (none without a sidecar).
Overrides SidecarOverrides(const std::filesystem::path& policy) {
  Overrides env;
  const std::filesystem::path sidecar = policy.string() + ".yaml";
  if (!std::filesystem::exists(sidecar)) return env;
  const YAML::Node root = LoadYamlFile(sidecar);
  if (root["env"] && root["env"].IsMap()) {
    for (const auto& item : root["env"]) {
      env.push_back("env." + item.first.as<std::string>() + "=" + item.second.as<std::string>());
    }
  }
  return env;
}

std::string GroupSuffix(const Overrides& env) {
  std::string suffix;
  for (const std::string& assignment : env) {
    suffix += "-" + assignment.substr(assignment.find('=') + 1);
  }
  return suffix;
}

// Adds `model` to the group of `prefix` + its env settings, creating the group on first use.
void AddToGroup(std::vector<EvaluationGroup>& groups, const std::string& prefix,
                const Overrides& env, const std::string& model,
                const std::filesystem::path& policy) {
  const std::string name = prefix + GroupSuffix(env);
  auto group = std::find_if(groups.begin(), groups.end(),
                            [&](const EvaluationGroup& g) { return g.name == name; });
  if (group == groups.end()) {
    groups.push_back({name, "", {}, {}, env, 0, 0});
    group = groups.end() - 1;
  }
  group->models.push_back(model);
  group->policies.push_back(policy);
}

std::vector<EvaluationGroup> GroupsOnScenarios(const StudySpec& spec,
                                               const std::filesystem::path& out,
                                               const std::string& scenarios, int episodes,
                                               std::uint64_t seed) {
  std::vector<EvaluationGroup> groups;
  for (const PpoConfigSpec& config : spec.ppo_configs) {
    Overrides all = spec.ppo_overrides;
    all.insert(all.end(), config.overrides.begin(), config.overrides.end());
    for (int k = 0; k < spec.ppo_seeds; ++k) {
      AddToGroup(groups, scenarios + "-ours", EnvironmentOverrides(all),
                 SeedModelName(config.name, k),
                 out / "ppo" / config.name / ("seed_" + std::to_string(k)) / "policy.pt");
    }
  }
  for (const std::filesystem::path& agent : spec.evaluation.reference_agents) {
    AddToGroup(groups, scenarios + "-reference", SidecarOverrides(agent),
               "ref." + agent.stem().string(), agent);
  }
  for (EvaluationGroup& group : groups) {
    group.scenario_set = scenarios;
    group.episodes = episodes;
    group.seed = seed;
  }
  return groups;
}

std::size_t AddJob(std::vector<StudyJob>& jobs, StudyJob job) {
  jobs.push_back(std::move(job));
  return jobs.size() - 1;
}

}  // namespace

std::string SeedModelName(const std::string& config, int seed) {
  return config + ".seed_" + std::to_string(seed);
}

std::vector<EvaluationGroup> EvaluationGroups(const StudySpec& spec,
                                              const std::filesystem::path& out) {
  std::vector<EvaluationGroup> groups =
      GroupsOnScenarios(spec, out, "study", spec.evaluation.episodes, spec.evaluation.seed);
  if (spec.evaluation.paper_episodes > 0) {
    const std::vector<EvaluationGroup> paper =
        GroupsOnScenarios(spec, out, "paper", spec.evaluation.paper_episodes, 0);
    groups.insert(groups.end(), paper.begin(), paper.end());
  }
  return groups;
}

std::vector<StudyJob> BuildJobGraph(const StudySpec& spec, const std::filesystem::path& out) {
  std::vector<StudyJob> jobs;
  const std::filesystem::path data = out / "data" / "scans.h5";
  StudyJob dataset{"data", "generate_dataset", {"--out", data.string()}, {}, data, {},
                   {},     kDatasetSeconds};
  AppendOverrides(dataset.args, spec.dataset_overrides);
  const std::size_t dataset_index = AddJob(jobs, dataset);

  std::map<std::string, std::size_t> vae_jobs;
  for (const VaeSpec& vae : spec.vaes) {
    const std::filesystem::path dir = out / "vae" / vae.name;
    StudyJob job{"vae/" + vae.name,
                 "train_vae",
                 {"--data", data.string(), "--model", vae.model, "--seeds",
                  std::to_string(vae.seeds), "--out", dir.string()},
                 {},
                 dir / "summary.json",
                 {},
                 {dataset_index},
                 kVaeSecondsPerSeed * vae.seeds};
    AppendOverrides(job.args, vae.overrides);
    vae_jobs[vae.name] = AddJob(jobs, job);
  }

  std::map<std::string, std::size_t> policy_jobs;  // policy.pt path -> the job that writes it
  for (const PpoConfigSpec& config : spec.ppo_configs) {
    for (int k = 0; k < spec.ppo_seeds; ++k) {
      const std::string id = "ppo/" + config.name + "/seed_" + std::to_string(k);
      const std::filesystem::path dir = out / id;
      StudyJob job{id,
                   "train_ppo",
                   {"--extractor", config.extractor},
                   {"--resume", dir.string()},
                   dir / "summary.json",
                   dir / "training_state.pt",
                   {},
                   static_cast<double>(spec.ppo_steps) / kPpoStepsPerSecond};
      if (config.extractor != "baseline") {
        const VaeSpec& vae = *std::find_if(spec.vaes.begin(), spec.vaes.end(),
                                           [&](const VaeSpec& v) { return v.name == config.vae; });
        // PPO seed k uses VAE seed k (cycling when the VAE has fewer seeds).
        const std::filesystem::path encoder =
            out / "vae" / vae.name / ("seed_" + std::to_string(k % vae.seeds)) / "encoder.pt";
        job.args.insert(job.args.end(),
                        {"--encoder", encoder.string(), config.locked ? "--locked" : "--unlocked"});
        job.dependencies.push_back(vae_jobs.at(config.vae));
      }
      job.args.insert(job.args.end(), {"--steps", std::to_string(spec.ppo_steps), "--seed",
                                       std::to_string(k), "--out", dir.string()});
      AppendOverrides(job.args, spec.ppo_overrides);
      AppendOverrides(job.args, config.overrides);
      job.check_configuration = k == 0;
      policy_jobs[(dir / "policy.pt").string()] = AddJob(jobs, job);
    }
  }

  for (const EvaluationGroup& group : EvaluationGroups(spec, out)) {
    const std::filesystem::path dir = out / "eval" / group.name;
    StudyJob job{
        "eval/" + group.name,
        "evaluate",
        {},
        {},
        dir / "summary.json",
        {},
        {},
        static_cast<double>(group.episodes * group.models.size()) / kEvaluationEpisodesPerSecond};
    for (std::size_t m = 0; m < group.models.size(); ++m) {
      const auto writer = policy_jobs.find(group.policies[m].string());
      if (writer != policy_jobs.end()) job.dependencies.push_back(writer->second);
      job.args.insert(job.args.end(),
                      {"--policy", group.policies[m].string(), "--name", group.models[m]});
    }
    job.args.insert(job.args.end(),
                    {"--episodes", std::to_string(group.episodes), "--seed",
                     std::to_string(group.seed), "--trajectories", "0", "--out", dir.string()});
    AppendOverrides(job.args, group.overrides);
    AddJob(jobs, job);
  }
  return jobs;
}

}  // namespace colav

#include "eval/evaluation_episodes.h"

#include <cstdio>
#include <map>

#include "env/angles.h"
#include "env/path.h"
#include "env/scenario_file.h"
#include "env/training_scenario.h"
#include "eval/safe_name.h"
#include "src/error.h"
#include "src/random.h"

namespace colav {

std::vector<EvaluationEpisode> TestEpisodes(std::uint64_t master_seed, int count) {
  const TrainingScenarioGenerator generator;
  std::vector<EvaluationEpisode> episodes;
  for (int k = 0; k < count; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "test-%03d", k);
    const std::uint64_t seed = TestScenarioSeed(master_seed, static_cast<std::uint64_t>(k));
    episodes.push_back({name, seed, generator.Make(seed)});
  }
  return episodes;
}

std::vector<EvaluationEpisode> ScenarioFileEpisodes(
    const std::vector<std::filesystem::path>& files) {
  std::vector<EvaluationEpisode> episodes;
  std::map<std::string, std::filesystem::path> file_of_name;
  for (const std::filesystem::path& file : files) {
    Scenario scenario = LoadScenarioFile(file);
    const std::string name = scenario.name.empty() ? file.stem().string() : scenario.name;
    RequireSafeName(name, file.string());
    const auto [previous, inserted] = file_of_name.emplace(name, file);
    if (!inserted) {
      throw UserError(file.string() + ": scenario name '" + name + "' is already used by " +
                      previous->second.string());
    }
    episodes.push_back({name, std::nullopt, std::move(scenario)});
  }
  return episodes;
}

EvaluationEpisode WithPerturbedStart(const EvaluationEpisode& episode, std::uint64_t master_seed,
                                     int index) {
  const TrainingScenarioConfig training;
  Rng rng =
      MakeRng(master_seed, "trajectory-start:" + episode.name, static_cast<std::uint64_t>(index));
  const Path path(episode.scenario.waypoints);
  EvaluationEpisode perturbed = episode;
  perturbed.name = episode.name + "-start" + std::to_string(index);
  const double offset_x = Uniform(rng, -training.start_offset, training.start_offset);
  const double offset_y = Uniform(rng, -training.start_offset, training.start_offset);
  perturbed.scenario.vessel_position = path.start() + Eigen::Vector2d(offset_x, offset_y);
  perturbed.scenario.vessel_heading = WrapAngle(path.Direction(0.0) + Uniform(rng, -kPi, kPi));
  perturbed.scenario.vessel_velocity.setZero();
  return perturbed;
}

}  // namespace colav

#include "env/training_scenario_config.h"

#include <cmath>

namespace colav {
namespace {

// More obstacles than this per world is a typo (the paper's worlds hold 17 and 11).
constexpr int kMaxObstacles = 200;
// Lateral spreads beyond this put every obstacle out of the range-finder's 150 m.
constexpr double kMaxDisplacementSd = 5000.0;
// The reference's paths have 1 or 2 bends (n / 2 for n in 2..5 waypoints).
constexpr int kMaxPathBends = 2;

}  // namespace

OptionsBinding<TrainingScenarioConfig> TrainingScenarioBinding(const std::string& prefix) {
  using World = TrainingScenarioConfig;
  OptionsBinding<World> binding;
  binding
      .Number(prefix + ".num_moving", &World::num_moving,
              "moving vessels per training world (the test scenarios keep the paper's 17)", 0,
              kMaxObstacles)
      .Number(prefix + ".moving_displacement_sd", &World::moving_displacement_sd,
              "standard deviation (m) of a vessel's lateral offset from the path (training)", 0.0,
              kMaxDisplacementSd)
      .Number(prefix + ".num_static", &World::num_static,
              "static circles per training world (the test scenarios keep the paper's 11)", 0,
              kMaxObstacles)
      .Number(prefix + ".static_displacement_sd", &World::static_displacement_sd,
              "standard deviation (m) of a circle's lateral offset from the path (training)", 0.0,
              kMaxDisplacementSd)
      .Number(prefix + ".path_bends", &World::path_bends,
              "bends of the path on each side of the origin: 0 draws 1 or 2 per episode; 1 or 2 "
              "fixes them (each of the authors' training worlds drew them once)",
              0, kMaxPathBends);
  return binding;
}

int SecondKindWorlds(double second_share, int num_worlds) {
  return static_cast<int>(std::lround(second_share * num_worlds));
}

std::vector<TrainingScenarioConfig> MixedWorlds(const TrainingScenarioConfig& first,
                                                const TrainingScenarioConfig& second,
                                                double second_share, int num_worlds) {
  const int second_count = SecondKindWorlds(second_share, num_worlds);
  std::vector<TrainingScenarioConfig> worlds(num_worlds - second_count, first);
  worlds.insert(worlds.end(), second_count, second);
  return worlds;
}

}  // namespace colav

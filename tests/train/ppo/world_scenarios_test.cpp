// The mix of training worlds a train_ppo run's world.*, world2.*, world2.share and
// world2.from_step keys give.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "src/config.h"
#include "src/error.h"
#include "train/ppo/config.h"

namespace colav {
namespace {

std::vector<TrainingScenarioConfig> ScenariosOf(
    const std::vector<std::pair<std::string, std::string>>& settings, std::int64_t step = 0) {
  Config config = Config::Defaults(PpoRunBinding().Schema());
  for (const auto& [key, value] : settings) config.Set(key, value, "test");
  return WorldScenarios(PpoRunBinding().Read(config), step);
}

TEST(WorldScenarios, EveryWorldIsThePapersByDefault) {
  const std::vector<TrainingScenarioConfig> scenarios = ScenariosOf({});
  ASSERT_EQ(scenarios.size(), 8U);
  for (const TrainingScenarioConfig& scenario : scenarios) {
    EXPECT_EQ(scenario.num_static, 11);
    EXPECT_EQ(scenario.num_moving, 17);
    EXPECT_EQ(scenario.static_displacement_sd, 250.0);
    EXPECT_EQ(scenario.moving_displacement_sd, 500.0);
  }
}

TEST(WorldScenarios, TheSecondKindTakesItsShareOfTheLastWorlds) {
  // 0.3 of 8 worlds: 2.4, so the last 2 play world2.
  const std::vector<TrainingScenarioConfig> scenarios =
      ScenariosOf({{"world.static_displacement_sd", "125"},
                   {"world2.moving_displacement_sd", "250"},
                   {"world2.share", "0.3"}});
  ASSERT_EQ(scenarios.size(), 8U);
  for (int world = 0; world < 8; ++world) {
    const bool second = world >= 6;
    EXPECT_EQ(scenarios[world].static_displacement_sd, second ? 250.0 : 125.0) << world;
    EXPECT_EQ(scenarios[world].moving_displacement_sd, second ? 250.0 : 500.0) << world;
  }
  EXPECT_EQ(ScenariosOf({{"ppo.n_envs", "4"}, {"world2.share", "1"}, {"world2.num_static", "3"}})
                .front()
                .num_static,
            3);
}

TEST(WorldScenarios, ACurriculumPlaysTheSecondKindFromItsStep) {
  const std::vector<std::pair<std::string, std::string>> curriculum = {
      {"world2.share", "1"}, {"world2.num_static", "3"}, {"world2.from_step", "1000"}};
  for (const std::int64_t step : {0, 999}) {
    for (const TrainingScenarioConfig& scenario : ScenariosOf(curriculum, step)) {
      EXPECT_EQ(scenario.num_static, 11) << step;
    }
  }
  for (const std::int64_t step : {1000, 5000}) {
    for (const TrainingScenarioConfig& scenario : ScenariosOf(curriculum, step)) {
      EXPECT_EQ(scenario.num_static, 3) << step;
    }
  }
}

TEST(WorldScenarios, ACurriculumNeedsWorldsForItsSecondStage) {
  Config config = Config::Defaults(PpoRunBinding().Schema());
  config.Set("world2.from_step", "1000", "test");
  EXPECT_THROW(PpoRunBinding().Read(config), UserError);
  config.Set("world2.share", "0.05", "test");  // 0.4 of the 8 worlds: none
  EXPECT_THROW(PpoRunBinding().Read(config), UserError);
  config.Set("world2.share", "0.125", "test");
  EXPECT_NO_THROW(PpoRunBinding().Read(config));
}

}  // namespace
}  // namespace colav

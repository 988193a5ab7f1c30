// Scenario files (reading, errors, round trip) and the training scenario generator.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "env/path.h"
#include "env/scenario_file.h"
#include "env/training_scenario.h"
#include "env/vessel_model.h"
#include "env/world.h"
#include "src/error.h"

namespace colav {
namespace {

class ScenarioFileTest : public ::testing::Test {
 protected:
  std::filesystem::path Write(const std::string& content) {
    const auto path = std::filesystem::temp_directory_path() /
                      ("colav_scenario_" + std::to_string(counter_++) + ".yaml");
    std::ofstream(path) << content;
    files_.push_back(path);
    return path;
  }
  // The one-line error message of loading `content`.
  std::string ErrorOf(const std::string& content) {
    try {
      LoadScenarioFile(Write(content));
    } catch (const UserError& e) {
      return e.what();
    }
    return "no error";
  }
  void TearDown() override {
    for (const auto& f : files_) std::filesystem::remove(f);
  }
  std::vector<std::filesystem::path> files_;
  int counter_ = 0;
};

constexpr const char* kValid = R"(name: crossing
path:
  waypoints: [[0, 0], [0, 250], [40, 500]]
vessel:
  position: [0, -10]
  heading: 1.5708
static_obstacles:
  - {position: [30, 120], radius: 20}
dynamic_obstacles:
  - {position: [-150, 300], width: 10, course: 0.0, speed: 0.5}
)";

TEST_F(ScenarioFileTest, ReadsAllFields) {
  const Scenario s = LoadScenarioFile(Write(kValid));
  EXPECT_EQ(s.name, "crossing");
  ASSERT_EQ(s.waypoints.size(), 3U);
  EXPECT_EQ(s.waypoints[2], Eigen::Vector2d(40, 500));
  EXPECT_EQ(s.vessel_position, Eigen::Vector2d(0, -10));
  EXPECT_DOUBLE_EQ(s.vessel_heading, 1.5708);
  EXPECT_EQ(s.vessel_velocity, Eigen::Vector3d::Zero());
  ASSERT_EQ(s.static_obstacles.size(), 1U);
  EXPECT_DOUBLE_EQ(s.static_obstacles[0].radius, 20.0);
  ASSERT_EQ(s.dynamic_obstacles.size(), 1U);
  EXPECT_DOUBLE_EQ(s.dynamic_obstacles[0].speed, 0.5);
}

TEST_F(ScenarioFileTest, RoundTripThroughYaml) {
  const Scenario generated = TrainingScenarioGenerator().Make(5);
  const Scenario read = LoadScenarioFile(Write(ScenarioToYaml(generated)));
  EXPECT_EQ(read.waypoints, generated.waypoints);
  EXPECT_EQ(read.vessel_position, generated.vessel_position);
  ASSERT_EQ(read.dynamic_obstacles.size(), generated.dynamic_obstacles.size());
  EXPECT_EQ(read.dynamic_obstacles[3].position, generated.dynamic_obstacles[3].position);
  EXPECT_EQ(read.static_obstacles[2].radius, generated.static_obstacles[2].radius);
}

TEST_F(ScenarioFileTest, BadFilesGiveOneLineErrorsNamingTheKey) {
  const auto expect_error = [&](const std::string& content, const std::string& fragment) {
    const std::string message = ErrorOf(content);
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("colav_scenario_"), std::string::npos) << message;
  };
  expect_error("vessel: {position: [0, 0], heading: 0}\n", "key 'path' is missing");
  expect_error("path: {waypoints: [[0, 0]]}\nvessel: {position: [0, 0], heading: 0}\n",
               "at least 2 waypoints");
  expect_error("path: {waypoints: [[0, 0], [1, 1]]}\nvessel: {position: [0, 0]}\n",
               "key 'vessel.heading' is missing");
  expect_error("path: {waypoints: [[0, 0], [1, 1]]}\nvessel: {position: [0, zero], heading: 0}\n",
               "key 'vessel.position[1]' expects a number, got 'zero'");
  expect_error(std::string("path: {waypoints: [[0, 0], [1, 1]]}\nvessel: {position: [0, 0], "
                           "heading: 0}\nstatic_obstacles:\n  - {position: [5, 5], radius: -3}\n"),
               "key 'static_obstacles[0].radius' must be positive");
  expect_error("path: {waypoints: [[0, 0], [0, 0]]}\nvessel: {position: [0, 0], heading: 0}\n",
               "key 'path.waypoints' has waypoints 0 and 1 only 0 m apart");
  expect_error("path: [unclosed\n", "malformed YAML");
  EXPECT_NE(std::string(ErrorOf(kValid)).find("no error"), std::string::npos);
  try {
    LoadScenarioFile("/nonexistent/scenario.yaml");
    FAIL() << "expected an error";
  } catch (const UserError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/scenario.yaml: no such file");
  }
}

// Values a simulation cannot run from (NaN after a step, a path polyline of 10^13 vertices) are
// refused with the key; so are keys the format does not have and keys given twice.
TEST_F(ScenarioFileTest, ImplausibleValuesAndUnknownKeysAreRefused) {
  const std::string vessel = "vessel: {position: [0, 0], heading: 0}\n";
  const std::string path = "path: {waypoints: [[0, 0], [0, 500]]}\n";
  const auto expect_error = [&](const std::string& content, const std::string& fragment) {
    const std::string message = ErrorOf(content);
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
  };
  expect_error("path: {waypoints: [[0, 0], [0, 1e12]]}\n" + vessel,
               "key 'path.waypoints[1][1]' = 1e12 is out of range [-100000, 100000]");
  expect_error("path: {waypoints: [[0, 0], [0, 1e-12]]}\n" + vessel,
               "key 'path.waypoints' has waypoints 0 and 1 only 1e-12 m apart (at least 0.1 m)");
  expect_error("path: {waypoints: [[0, 0], [0, 0.5]]}\n" + vessel,
               "key 'path.waypoints' is 0.5 m long; a path is 1 to 100000 m");
  expect_error(path + "vessel: {position: [0, 0], heading: 0, velocity: [1e200, 0, 0]}\n",
               "key 'vessel.velocity[0]' = 1e200 is out of range [-1, 1]");
  expect_error(path + "vessel: {position: [0, 0], heading: .nan}\n",
               "key 'vessel.heading' expects a number, got '.nan'");
  expect_error(path + vessel +
                   "dynamic_obstacles:\n  - {position: [1, 1], width: 5, course: 0, "
                   "speed: 1e6}\n",
               "key 'dynamic_obstacles[0].speed' = 1e6 is out of range [0, 100]");
  expect_error(path + vessel + "obstacles: []\n", "unknown key 'obstacles'");
  expect_error(path + "vessel: {position: [0, 0], heading: 0, speed: 1}\n",
               "unknown key 'vessel.speed'");
  expect_error(path + vessel + vessel, "duplicate key 'vessel'");
  expect_error("name: {a: 1}\n" + path + vessel, "key 'name' expects a text");
}

// The largest plausible start still simulates to finite states under hard turns at full thrust.
TEST_F(ScenarioFileTest, FastestPlausibleStartStaysFinite) {
  const Scenario scenario = LoadScenarioFile(
      Write("path: {waypoints: [[0, 0], [0, 500], [300, 900]]}\n"
            "vessel: {position: [0, 0], heading: 0, velocity: [-1, 0.5, -0.5]}\n"));
  VesselState state;
  state << 0, 0, 0, scenario.vessel_velocity;
  for (int step = 0; step < 1000; ++step) {
    const GeneralisedForce tau = CybershipModel::ForceFromAction(1.0, step % 100 < 50 ? 1.0 : -1.0);
    state = CybershipModel::Step(state, tau, kTimeStep);
    ASSERT_TRUE(state.allFinite()) << "step " << step;
  }
}

TEST(TrainingScenario, PaperCountsAndPlacementRules) {
  const TrainingScenarioGenerator generator;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const Scenario s = generator.Make(seed);
    ASSERT_EQ(s.dynamic_obstacles.size(), 17U);
    ASSERT_EQ(s.static_obstacles.size(), 11U);
    ASSERT_TRUE(s.waypoints.size() == 5 || s.waypoints.size() == 7) << s.waypoints.size();
    EXPECT_NEAR(s.waypoints.front().norm(), 150.0, 1e-9);
    const Path path(s.waypoints);
    EXPECT_LE((s.vessel_position - path.start()).cwiseAbs().maxCoeff(), 25.0);
    for (const CircleSpec& c : s.static_obstacles) {
      EXPECT_GE(c.radius, 1.0);
      EXPECT_GT((c.center - s.vessel_position).norm() - CybershipModel::kRadius - c.radius, 100.0);
      EXPECT_GT((c.center - path.end()).norm() - c.radius, 100.0);
    }
    for (const VesselObstacleSpec& v : s.dynamic_obstacles) {
      EXPECT_GE(v.speed, 0.0597);
      EXPECT_LE(v.speed, 1.9875);
    }
  }
  // The number of waypoints is drawn per episode: both layouts occur.
  std::set<std::size_t> layouts;
  for (std::uint64_t seed = 0; seed < 40; ++seed)
    layouts.insert(generator.Make(seed).waypoints.size());
  EXPECT_EQ(layouts.size(), 2U);
}

// path_bends fixes the layout (5 waypoints for one bend a side, 7 for two) and changes nothing
// else: a scenario whose drawn layout already has that many bends comes out the same.
TEST(TrainingScenario, PathBendsFixTheLayoutAndNothingElse) {
  const TrainingScenarioGenerator drawn;
  for (const int bends : {1, 2}) {
    TrainingScenarioConfig config;
    config.path_bends = bends;
    const TrainingScenarioGenerator fixed(config);
    const std::size_t waypoints = 2 * static_cast<std::size_t>(bends) + 3;
    int alike = 0;
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
      const Scenario s = fixed.Make(seed);
      ASSERT_EQ(s.waypoints.size(), waypoints) << "seed " << seed;
      const Scenario d = drawn.Make(seed);
      if (d.waypoints.size() != waypoints) continue;
      ++alike;
      EXPECT_EQ(s.waypoints, d.waypoints);
      EXPECT_EQ(s.vessel_position, d.vessel_position);
      ASSERT_EQ(s.static_obstacles.size(), d.static_obstacles.size());
      EXPECT_EQ(s.static_obstacles.back().center, d.static_obstacles.back().center);
    }
    EXPECT_GT(alike, 5) << bends;
  }
}

TEST(TrainingScenario, CountsAndSpreadsAreConfigurable) {
  TrainingScenarioConfig config;
  config.num_moving = 0;
  config.num_static = 25;
  config.static_displacement_sd = 10.0;
  const TrainingScenarioGenerator generator(config);
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const Scenario s = generator.Make(seed);
    EXPECT_TRUE(s.dynamic_obstacles.empty());
    ASSERT_EQ(s.static_obstacles.size(), 25U);
    const Path path(s.waypoints);
    for (const CircleSpec& c : s.static_obstacles) {
      // Placed at most 6 standard deviations off the path (the default spread is 250 m).
      EXPECT_LT((path.Point(path.ClosestArclength(c.center)) - c.center).norm(), 60.0);
    }
  }
}

TEST(TrainingScenario, SpeedTableInverseCdf) {
  EXPECT_DOUBLE_EQ(MovingObstacleSpeed(0.0), 5.973753401783561678e-02);
  EXPECT_NEAR(MovingObstacleSpeed(0.999999999), 1.987489866097870594, 1e-12);
  // Cumulative probability of the first entry is 0.01206554933469061210.
  EXPECT_DOUBLE_EQ(MovingObstacleSpeed(0.0120), MovingObstacleSpeed(0.0));
  EXPECT_GT(MovingObstacleSpeed(0.0121), MovingObstacleSpeed(0.0));
}

}  // namespace
}  // namespace colav

#include "env/scenario_file.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "src/error.h"
#include "src/yaml_file.h"

namespace colav {
namespace {

// Reads typed values from a YAML node, with errors that name the file and the key.
class ScenarioReader {
 public:
  explicit ScenarioReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void Fail(const std::string& key, const std::string& problem) const {
    throw UserError(file_ + ": " + (key.empty() ? "" : "key '" + key + "' ") + problem);
  }

  YAML::Node Required(const YAML::Node& parent, const std::string& name,
                      const std::string& key) const {
    if (!parent.IsMap() || !parent[name]) Fail(key, "is missing");
    return parent[name];
  }

  double Number(const YAML::Node& node, const std::string& key) const {
    if (!node.IsScalar()) Fail(key, "expects a number");
    try {
      const double value = node.as<double>();
      if (!std::isfinite(value)) Fail(key, "expects a finite number, got '" + node.Scalar() + "'");
      return value;
    } catch (const YAML::Exception&) {
      Fail(key, "expects a number, got '" + node.Scalar() + "'");
    }
  }

  Eigen::Vector2d Point(const YAML::Node& node, const std::string& key) const {
    if (!node.IsSequence() || node.size() != 2) Fail(key, "expects a pair [x, y]");
    return {Number(node[0], key + "[0]"), Number(node[1], key + "[1]")};
  }

  std::vector<Eigen::Vector2d> Waypoints(const YAML::Node& root) const {
    const std::string key = "path.waypoints";
    const YAML::Node node = Required(Required(root, "path", "path"), "waypoints", key);
    if (!node.IsSequence() || node.size() < 2) Fail(key, "needs at least 2 waypoints");
    std::vector<Eigen::Vector2d> waypoints;
    for (std::size_t k = 0; k < node.size(); ++k) {
      waypoints.push_back(Point(node[k], key + "[" + std::to_string(k) + "]"));
      if (k > 0 && waypoints[k] == waypoints[k - 1]) {
        Fail(key, "has two equal consecutive waypoints at index " + std::to_string(k));
      }
    }
    return waypoints;
  }

  void Vessel(const YAML::Node& root, Scenario& scenario) const {
    const YAML::Node vessel = Required(root, "vessel", "vessel");
    scenario.vessel_position =
        Point(Required(vessel, "position", "vessel.position"), "vessel.position");
    scenario.vessel_heading =
        Number(Required(vessel, "heading", "vessel.heading"), "vessel.heading");
    if (const YAML::Node velocity = vessel["velocity"]) {
      if (!velocity.IsSequence() || velocity.size() != 3) {
        Fail("vessel.velocity", "expects [u, v, r]");
      }
      for (int k = 0; k < 3; ++k) {
        scenario.vessel_velocity[k] = Number(velocity[k], "vessel.velocity");
      }
    }
  }

  double Positive(const YAML::Node& parent, const std::string& name, const std::string& key) const {
    const double value = Number(Required(parent, name, key), key);
    if (value <= 0.0) Fail(key, "must be positive, got " + Required(parent, name, key).Scalar());
    return value;
  }

  YAML::Node OptionalList(const YAML::Node& root, const std::string& key) const {
    const YAML::Node node = root[key];
    if (node && !node.IsNull() && !node.IsSequence()) Fail(key, "expects a list");
    return node;
  }

  void Obstacles(const YAML::Node& root, Scenario& scenario) const {
    const YAML::Node circles = OptionalList(root, "static_obstacles");
    for (std::size_t k = 0; circles && k < circles.size(); ++k) {
      const std::string key = "static_obstacles[" + std::to_string(k) + "]";
      scenario.static_obstacles.push_back(
          {Point(Required(circles[k], "position", key + ".position"), key + ".position"),
           Positive(circles[k], "radius", key + ".radius")});
    }
    const YAML::Node vessels = OptionalList(root, "dynamic_obstacles");
    for (std::size_t k = 0; vessels && k < vessels.size(); ++k) {
      const std::string key = "dynamic_obstacles[" + std::to_string(k) + "]";
      VesselObstacleSpec obstacle;
      obstacle.position =
          Point(Required(vessels[k], "position", key + ".position"), key + ".position");
      obstacle.width = Positive(vessels[k], "width", key + ".width");
      obstacle.course = Number(Required(vessels[k], "course", key + ".course"), key + ".course");
      obstacle.speed = Number(Required(vessels[k], "speed", key + ".speed"), key + ".speed");
      if (obstacle.speed < 0.0) Fail(key + ".speed", "must not be negative");
      scenario.dynamic_obstacles.push_back(obstacle);
    }
  }

 private:
  std::string file_;
};

}  // namespace

Scenario LoadScenarioFile(const std::filesystem::path& path) {
  const std::string file = path.string();
  const YAML::Node root = LoadYamlFile(path);
  const ScenarioReader reader(file);
  if (!root.IsMap()) reader.Fail("", "expects a mapping with keys path, vessel, ...");
  Scenario scenario;
  scenario.name = root["name"] ? root["name"].as<std::string>() : path.stem().string();
  scenario.waypoints = reader.Waypoints(root);
  reader.Vessel(root, scenario);
  reader.Obstacles(root, scenario);
  return scenario;
}

std::string ScenarioToYaml(const Scenario& scenario) {
  std::ostringstream out;
  out << std::setprecision(17);
  const auto pair = [&](const Eigen::Vector2d& p) { out << "[" << p.x() << ", " << p.y() << "]"; };
  out << "name: " << scenario.name << "\npath:\n  waypoints: [";
  for (std::size_t k = 0; k < scenario.waypoints.size(); ++k) {
    if (k > 0) out << ", ";
    pair(scenario.waypoints[k]);
  }
  out << "]\nvessel:\n  position: ";
  pair(scenario.vessel_position);
  out << "\n  heading: " << scenario.vessel_heading << "\n  velocity: ["
      << scenario.vessel_velocity[0] << ", " << scenario.vessel_velocity[1] << ", "
      << scenario.vessel_velocity[2] << "]\n";
  out << "static_obstacles:" << (scenario.static_obstacles.empty() ? " []" : "") << "\n";
  for (const CircleSpec& circle : scenario.static_obstacles) {
    out << "  - {position: ";
    pair(circle.center);
    out << ", radius: " << circle.radius << "}\n";
  }
  out << "dynamic_obstacles:" << (scenario.dynamic_obstacles.empty() ? " []" : "") << "\n";
  for (const VesselObstacleSpec& vessel : scenario.dynamic_obstacles) {
    out << "  - {position: ";
    pair(vessel.position);
    out << ", width: " << vessel.width << ", course: " << vessel.course
        << ", speed: " << vessel.speed << "}\n";
  }
  return out.str();
}

}  // namespace colav

#include "env/scenario_file.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <iomanip>
#include <optional>
#include <set>
#include <sstream>

#include "src/error.h"
#include "src/number_text.h"
#include "src/yaml_file.h"

namespace colav {
namespace {

// Plausible ranges of a scenario's numbers. A value outside them is a typo (a unit or an exponent
// off) that would make the simulation overflow to NaN, or the path's projection polyline (10
// vertices per metre) allocate without bound.
constexpr double kMaxCoordinate = 1e5;       // m from the origin
constexpr double kMinPathLength = 1.0;       // m along the waypoints: the path needs 1 m
constexpr double kMaxPathLength = 1e5;       // m along the waypoints
constexpr double kMinWaypointSpacing = 0.1;  // m between consecutive waypoints
constexpr double kMaxAngle = 100.0;          // rad, headings and courses (wrapped later)
// The vessel model, one RKF45 step per second, diverges to NaN from faster starts (measured: surge
// 2.5 m/s alone, or surge 1.5 with sway 1); full thrust reaches well under 1 m/s.
constexpr double kMaxSurge = 1.0;            // m/s
constexpr double kMaxSway = 0.5;             // m/s
constexpr double kMaxYawRate = 0.5;          // rad/s
constexpr double kMaxRadius = 1e4;           // m, static obstacles
constexpr double kMaxWidth = 1e3;            // m, moving obstacles
constexpr double kMaxObstacleSpeed = 100.0;  // m/s

struct Range {
  double min;
  double max;
};
constexpr Range kCoordinate{-kMaxCoordinate, kMaxCoordinate};
constexpr Range kAngle{-kMaxAngle, kMaxAngle};

// The keys a scenario file may hold, per level (shared/spec/interfaces.md).
const std::set<std::string> kTopKeys = {"name", "path", "vessel", "static_obstacles",
                                        "dynamic_obstacles"};
const std::set<std::string> kPathKeys = {"waypoints"};
const std::set<std::string> kVesselKeys = {"position", "heading", "velocity"};
const std::set<std::string> kCircleKeys = {"position", "radius"};
const std::set<std::string> kMovingKeys = {"position", "width", "course", "speed"};

// Reads typed values from a YAML node, with errors that name the file and the key.
class ScenarioReader {
 public:
  explicit ScenarioReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void Fail(const std::string& key, const std::string& problem) const {
    throw UserError(file_ + ": " + (key.empty() ? "" : "key '" + key + "' ") + problem);
  }

  // A map holding only `allowed` keys; `prefix` names it in errors ("" at the top level).
  void RequireKnownKeys(const YAML::Node& node, const std::set<std::string>& allowed,
                        const std::string& prefix) const {
    if (!node.IsMap()) Fail(prefix, "expects a map of keys");
    for (const auto& item : node) {
      const std::string name = item.first.Scalar();
      if (allowed.count(name) == 0) {
        std::string key = prefix;
        if (!key.empty()) key += '.';
        key += name;
        Fail("", "unknown key '" + key + "'");
      }
    }
  }

  YAML::Node Required(const YAML::Node& parent, const std::string& name,
                      const std::string& key) const {
    if (!parent.IsMap() || !parent[name]) Fail(key, "is missing");
    return parent[name];
  }

  double Number(const YAML::Node& node, const std::string& key, Range range) const {
    if (!node.IsScalar()) Fail(key, "expects a number");
    const std::optional<double> value = ParseFiniteNumber(node.Scalar());
    if (!value) Fail(key, "expects a number, got '" + node.Scalar() + "'");
    if (*value < range.min || *value > range.max) {
      Fail(key, "= " + node.Scalar() + " is out of range " + RangeText(range.min, range.max));
    }
    return *value;
  }

  Eigen::Vector2d Point(const YAML::Node& node, const std::string& key) const {
    if (!node.IsSequence() || node.size() != 2) Fail(key, "expects a pair [x, y]");
    return {Number(node[0], key + "[0]", kCoordinate), Number(node[1], key + "[1]", kCoordinate)};
  }

  std::vector<Eigen::Vector2d> Waypoints(const YAML::Node& root) const {
    const std::string key = "path.waypoints";
    const YAML::Node path = Required(root, "path", "path");
    RequireKnownKeys(path, kPathKeys, "path");
    const YAML::Node node = Required(path, "waypoints", key);
    if (!node.IsSequence() || node.size() < 2) Fail(key, "needs at least 2 waypoints");
    std::vector<Eigen::Vector2d> waypoints;
    double length = 0.0;
    for (std::size_t k = 0; k < node.size(); ++k) {
      waypoints.push_back(Point(node[k], key + "[" + std::to_string(k) + "]"));
      if (k == 0) continue;
      const double spacing = (waypoints[k] - waypoints[k - 1]).norm();
      if (spacing < kMinWaypointSpacing) {
        Fail(key, fmt::format("has waypoints {} and {} only {:g} m apart (at least {:g} m)", k - 1,
                              k, spacing, kMinWaypointSpacing));
      }
      length += spacing;
    }
    if (length < kMinPathLength || length > kMaxPathLength) {
      Fail(key, fmt::format("is {:g} m long; a path is {:g} to {:g} m", length, kMinPathLength,
                            kMaxPathLength));
    }
    return waypoints;
  }

  void Vessel(const YAML::Node& root, Scenario& scenario) const {
    const YAML::Node vessel = Required(root, "vessel", "vessel");
    RequireKnownKeys(vessel, kVesselKeys, "vessel");
    scenario.vessel_position =
        Point(Required(vessel, "position", "vessel.position"), "vessel.position");
    scenario.vessel_heading =
        Number(Required(vessel, "heading", "vessel.heading"), "vessel.heading", kAngle);
    if (const YAML::Node velocity = vessel["velocity"]) {
      if (!velocity.IsSequence() || velocity.size() != 3) {
        Fail("vessel.velocity", "expects [u, v, r]");
      }
      const std::array<Range, 3> ranges = {Range{-kMaxSurge, kMaxSurge}, Range{-kMaxSway, kMaxSway},
                                           Range{-kMaxYawRate, kMaxYawRate}};
      for (int k = 0; k < 3; ++k) {
        scenario.vessel_velocity[k] =
            Number(velocity[k], "vessel.velocity[" + std::to_string(k) + "]",
                   ranges[static_cast<std::size_t>(k)]);
      }
    }
  }

  // A radius or width: positive (0 has no shape) and at most `max`.
  double Size(const YAML::Node& parent, const std::string& name, const std::string& key,
              double max) const {
    const YAML::Node node = Required(parent, name, key);
    const double value = Number(node, key, {-max, max});
    if (value <= 0.0) Fail(key, "must be positive, got " + node.Scalar());
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
      RequireKnownKeys(circles[k], kCircleKeys, key);
      scenario.static_obstacles.push_back(
          {Point(Required(circles[k], "position", key + ".position"), key + ".position"),
           Size(circles[k], "radius", key + ".radius", kMaxRadius)});
    }
    const YAML::Node vessels = OptionalList(root, "dynamic_obstacles");
    for (std::size_t k = 0; vessels && k < vessels.size(); ++k) {
      const std::string key = "dynamic_obstacles[" + std::to_string(k) + "]";
      RequireKnownKeys(vessels[k], kMovingKeys, key);
      VesselObstacleSpec obstacle;
      obstacle.position =
          Point(Required(vessels[k], "position", key + ".position"), key + ".position");
      obstacle.width = Size(vessels[k], "width", key + ".width", kMaxWidth);
      obstacle.course =
          Number(Required(vessels[k], "course", key + ".course"), key + ".course", kAngle);
      obstacle.speed = Number(Required(vessels[k], "speed", key + ".speed"), key + ".speed",
                              {0.0, kMaxObstacleSpeed});
      scenario.dynamic_obstacles.push_back(obstacle);
    }
  }

  std::string Name(const YAML::Node& root, const std::filesystem::path& path) const {
    const YAML::Node name = root["name"];
    if (!name) return path.stem().string();
    if (!name.IsScalar()) Fail("name", "expects a text");
    return name.Scalar();
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
  reader.RequireKnownKeys(root, kTopKeys, "");
  Scenario scenario;
  scenario.name = reader.Name(root, path);
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

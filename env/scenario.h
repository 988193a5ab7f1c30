// A scenario: one episode's initial world (path waypoints, vessel state, obstacles).
//
// Scenarios come from a ScenarioSource: the paper's random training worlds
// (TrainingScenarioGenerator) or a fixed scenario file (scenario_file.h).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace colav {

/// A static circular obstacle.
struct CircleSpec {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radius = 1.0;
};

/// A moving vessel: pentagon hull of width `width` (reference-simulator 5.2), rotated by
/// `course` about `position`, moving with speed * (cos course, sin course).
struct VesselObstacleSpec {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< at the reset observation
  double width = 10.0;
  double course = 0.0;
  double speed = 0.0;
};

struct Scenario {
  std::string name;
  std::vector<Eigen::Vector2d> waypoints;  ///< raw, smoothed by Path
  Eigen::Vector2d vessel_position = Eigen::Vector2d::Zero();
  double vessel_heading = 0.0;
  Eigen::Vector3d vessel_velocity = Eigen::Vector3d::Zero();  ///< u, v, r
  std::vector<CircleSpec> static_obstacles;
  std::vector<VesselObstacleSpec> dynamic_obstacles;
};

/// Where an environment's episodes come from; Make must be a pure function of the seed.
class ScenarioSource {
 public:
  virtual ~ScenarioSource() = default;
  virtual Scenario Make(std::uint64_t seed) const = 0;
};

}  // namespace colav

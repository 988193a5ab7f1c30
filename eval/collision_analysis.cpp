#include "eval/collision_analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "env/angles.h"
#include "env/range_finder.h"
#include "env/world.h"
#include "eval/collision_avoidability.h"

namespace colav {
namespace {

constexpr double kRadiansToDegrees = 180.0 / M_PI;

// Distance from our vessel's centre to each obstacle: the moving vessels, then the static ones.
std::vector<double> ObstacleDistances(const World& world) {
  const Eigen::Vector2d position = world.vessel().head<2>();
  std::vector<double> distances;
  for (const MovingObstacle& obstacle : world.moving_obstacles()) {
    distances.push_back(DistanceToPolygon(position, obstacle.hull()));
  }
  for (const CircleSpec& circle : world.static_obstacles()) {
    distances.push_back(std::max(0.0, (circle.center - position).norm() - circle.radius));
  }
  return distances;
}

// The moving vessels after `step` steps: they hold their course whatever our vessel does, so
// they are advanced as World::Advance advances them, without replaying the episode.
std::vector<MovingObstacle> MovingObstaclesAt(const Scenario& scenario, int step) {
  std::vector<MovingObstacle> vessels;
  for (const VesselObstacleSpec& spec : scenario.dynamic_obstacles) {
    vessels.emplace_back(spec);
    for (int k = 0; k < step; ++k) vessels.back().Advance(kTimeStep);
  }
  return vessels;
}

// Whether some candidate manoeuvre, started after `start` steps of the episode from our vessel's
// state then, stays clear until kClearAfterContact steps after the contact.
bool AvoidableFrom(const Scenario& scenario, const VesselState& vessel, int start,
                   int contact_step) {
  const AvoidanceSearch search(scenario.static_obstacles, MovingObstaclesAt(scenario, start));
  return search.FindClearManoeuvre(vessel, contact_step - start + kClearAfterContact).has_value();
}

}  // namespace

std::optional<CollisionAnalysis> AnalyseCollision(
    const Scenario& scenario, const std::vector<std::array<float, kActionSize>>& actions) {
  World world;
  world.Load(scenario);
  std::vector<std::vector<double>> distances = {ObstacleDistances(world)};
  std::vector<VesselState> vessel_states = {world.vessel()};
  CollisionAnalysis analysis;
  for (std::size_t step = 0; step < actions.size() && !world.collision(); ++step) {
    world.Advance(CybershipModel::ForceFromAction(actions[step][0], actions[step][1]));
    distances.push_back(ObstacleDistances(world));
    vessel_states.push_back(world.vessel());
  }
  if (!world.collision()) return std::nullopt;
  analysis.contact_step = static_cast<int>(distances.size()) - 1;
  const std::vector<double>& at_contact = distances.back();
  const int hit =
      static_cast<int>(std::min_element(at_contact.begin(), at_contact.end()) - at_contact.begin());
  const int moving_count = static_cast<int>(world.moving_obstacles().size());
  analysis.moving_obstacle = hit < moving_count;
  analysis.obstacle = analysis.moving_obstacle ? hit : hit - moving_count;
  const Eigen::Vector2d centre = analysis.moving_obstacle
                                     ? world.moving_obstacles()[hit].position()
                                     : world.static_obstacles()[analysis.obstacle].center;
  if (analysis.moving_obstacle) {
    analysis.obstacle_speed = world.moving_obstacles()[hit].spec().speed;
  }
  const Eigen::Vector2d offset = centre - world.vessel().head<2>();
  analysis.bearing_deg =
      WrapAngle(std::atan2(offset.y(), offset.x()) - world.vessel()[2]) * kRadiansToDegrees;
  while (distances[analysis.detection_step][hit] > RangeFinder::kRange) ++analysis.detection_step;
  const auto avoidable_from = [&](int start) {
    return AvoidableFrom(scenario, vessel_states[start], start, analysis.contact_step);
  };
  analysis.avoidable_from_detection = avoidable_from(analysis.detection_step);
  for (std::size_t k = 0; k < kCollisionLeadTimes.size(); ++k) {
    analysis.avoidable_before[k] =
        avoidable_from(std::max(0, analysis.contact_step - kCollisionLeadTimes[k]));
  }
  return analysis;
}

std::string CollisionCsvHeader() {
  std::string header =
      "model,scenario,contact_step,obstacle,obstacle_index,obstacle_speed,bearing_deg,"
      "detection_step,warning_s,avoidable_from_detection";
  for (const int lead : kCollisionLeadTimes) header += fmt::format(",avoidable_{}s_before", lead);
  return header + "\n";
}

std::string CollisionCsvRow(const std::string& model, const std::string& scenario,
                            const CollisionAnalysis& analysis) {
  std::string row = fmt::format(
      "{},{},{},{},{},{:.3f},{:.1f},{},{},{:d}", model, scenario, analysis.contact_step,
      analysis.moving_obstacle ? "vessel" : "static", analysis.obstacle, analysis.obstacle_speed,
      analysis.bearing_deg, analysis.detection_step,
      analysis.contact_step - analysis.detection_step, analysis.avoidable_from_detection);
  for (const bool avoidable : analysis.avoidable_before) row += fmt::format(",{:d}", avoidable);
  return row + "\n";
}

std::string CollisionSummaryMarkdown(const std::vector<CollisionCounts>& models) {
  std::string table =
      "| model | episodes | collisions | with moving vessels | not avoidable once in range |";
  std::string rule = "|---|---|---|---|---|";
  for (const int lead : kCollisionLeadTimes) {
    table += fmt::format(" not avoidable {} s before |", lead);
    rule += "---|";
  }
  table += "\n" + rule + "\n";
  for (const CollisionCounts& model : models) {
    const auto share = [&](int count) {
      return fmt::format("{} ({:.1f} %)", count, 100.0 * count / std::max(model.episodes, 1));
    };
    const auto count_if = [&](auto predicate) {
      return static_cast<int>(
          std::count_if(model.collisions.begin(), model.collisions.end(), predicate));
    };
    table += fmt::format(
        "| {} | {} | {} | {} | {} |", model.model, model.episodes,
        share(static_cast<int>(model.collisions.size())),
        share(count_if([](const CollisionAnalysis& c) { return c.moving_obstacle; })),
        share(count_if([](const CollisionAnalysis& c) { return !c.avoidable_from_detection; })));
    for (std::size_t k = 0; k < kCollisionLeadTimes.size(); ++k) {
      table += fmt::format(
          " {} |",
          share(count_if([&](const CollisionAnalysis& c) { return !c.avoidable_before[k]; })));
    }
    table += "\n";
  }
  return table;
}

}  // namespace colav

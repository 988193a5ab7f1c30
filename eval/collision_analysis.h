// Why an evaluation episode ended in a collision, and whether it had to: the episode is replayed
// from its scenario and the actions the policy took, the obstacle hit is named, the step at which
// it first came within the range finder's 150 m is found, and manoeuvres are searched from that
// step and from fixed lead times before the contact (collision_avoidability.h). A collision for
// which no manoeuvre exists once the obstacle is in range is one no policy acting on its sensor
// could have avoided from where this one was.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "env/environment_spec.h"
#include "env/scenario.h"

namespace colav {

/// Seconds before the contact from which avoidance is also searched.
inline constexpr std::array<int, 3> kCollisionLeadTimes = {10, 30, 60};
/// Steps after the contact a manoeuvre must also stay clear for (the obstacle has passed).
inline constexpr int kClearAfterContact = 100;

struct CollisionAnalysis {
  int contact_step = 0;          ///< the step after which the vessel touched the obstacle
  bool moving_obstacle = false;  ///< a moving vessel, else a static obstacle
  int obstacle = 0;              ///< index among the scenario's moving (or static) obstacles
  double obstacle_speed = 0.0;   ///< m/s
  double bearing_deg = 0.0;      ///< obstacle centre from our bow at contact, (-180, 180], port +
  int detection_step = 0;        ///< first step with the obstacle within 150 m of our vessel
  bool avoidable_from_detection = false;
  std::array<bool, kCollisionLeadTimes.size()> avoidable_before{};  ///< per lead time
};

/// The collision of `scenario` under `actions` (actions[k] leads from step k to k + 1), or
/// nullopt when these actions do not collide.
std::optional<CollisionAnalysis> AnalyseCollision(
    const Scenario& scenario, const std::vector<std::array<float, kActionSize>>& actions);

/// One model's collisions as CSV rows (with `header`): model, scenario, then the fields above.
std::string CollisionCsvHeader();
std::string CollisionCsvRow(const std::string& model, const std::string& scenario,
                            const CollisionAnalysis& analysis);

/// Per model: episodes, collisions, those with moving vessels, and those not avoidable once in
/// range and 10, 30 and 60 s before the contact; as a Markdown table.
struct CollisionCounts {
  std::string model;
  int episodes = 0;
  std::vector<CollisionAnalysis> collisions;
};
std::string CollisionSummaryMarkdown(const std::vector<CollisionCounts>& models);

}  // namespace colav

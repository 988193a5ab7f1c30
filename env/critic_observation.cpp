#include "env/critic_observation.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "env/range_finder.h"
#include "env/vessel_model.h"
#include "env/world.h"

namespace colav {
namespace {

constexpr double kWidthScale = 10.0;  // m

}  // namespace

void WriteCriticObservation(const World& world, int vessels, float* out) {
  std::fill(out, out + CriticObservationSize(vessels), 0.0f);
  if (vessels == 0) return;
  const VesselState& agent = world.vessel();
  const Eigen::Vector2d position(agent[0], agent[1]);
  const double cos_psi = std::cos(agent[2]);
  const double sin_psi = std::sin(agent[2]);
  // World to body frame: the transpose of the heading's rotation.
  const auto to_body = [&](const Eigen::Vector2d& w) {
    return Eigen::Vector2d(cos_psi * w.x() + sin_psi * w.y(), -sin_psi * w.x() + cos_psi * w.y());
  };
  const Eigen::Vector2d agent_velocity(cos_psi * agent[3] - sin_psi * agent[4],
                                       sin_psi * agent[3] + cos_psi * agent[4]);

  const std::vector<MovingObstacle>& obstacles = world.moving_obstacles();
  std::vector<std::pair<double, int>> nearest;  // (distance, index), within range
  for (int i = 0; i < static_cast<int>(obstacles.size()); ++i) {
    const double distance = (obstacles[i].position() - position).norm();
    if (distance <= kCriticVesselRange) nearest.emplace_back(distance, i);
  }
  const int shown = std::min(vessels, static_cast<int>(nearest.size()));
  std::partial_sort(nearest.begin(), nearest.begin() + shown, nearest.end());
  for (int k = 0; k < shown; ++k) {
    const MovingObstacle& obstacle = obstacles[nearest[k].second];
    const Eigen::Vector2d offset = to_body(obstacle.position() - position) / RangeFinder::kRange;
    const Eigen::Vector2d velocity =
        to_body(obstacle.velocity() - agent_velocity) / CybershipModel::kMaxSpeed;
    float* slot = out + k * kCriticValuesPerVessel;
    slot[0] = 1.0f;
    slot[1] = static_cast<float>(offset.x());
    slot[2] = static_cast<float>(offset.y());
    slot[3] = static_cast<float>(velocity.x());
    slot[4] = static_cast<float>(velocity.y());
    slot[5] = static_cast<float>(obstacle.spec().width / kWidthScale);
  }
}

}  // namespace colav

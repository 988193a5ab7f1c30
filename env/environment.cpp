#include "env/environment.h"

#include <algorithm>
#include <cmath>

#include "env/reward.h"

namespace colav {
namespace {

// The observation scales the cross-track error by this (reference-simulator 6.4).
constexpr double kCteObservationScale = 100.0;

}  // namespace

Environment::Environment(EnvironmentConfig config, std::shared_ptr<const ScenarioSource> source)
    : config_(config),
      source_(std::move(source)),
      world_(config_.obstacle_list_refresh),
      scan_ring_(config_.scan_history == 0 ? 0
                                           : static_cast<std::size_t>(config_.scan_history) *
                                                     config_.scan_history_interval * kNumRays +
                                                 kNumRays) {}

void Environment::Reset(std::uint64_t seed, float* observation) {
  world_.Load(source_->Make(seed));
  steps_ = 0;
  cumulative_reward_ = 0.0;
  sum_abs_cte_ = 0.0;
  WriteObservation(observation);
}

StepResult Environment::Step(const double* action, float* observation) {
  world_.Advance(CybershipModel::ForceFromAction(action[0], action[1]));
  ++steps_;
  const VesselState& vessel = world_.vessel();
  const NavigationState& nav = world_.navigation();
  StepResult result;
  result.collision = world_.collision();
  result.reward = PathReward(std::hypot(vessel[3], vessel[4]), nav.heading_error,
                             nav.cross_track_error, result.collision);
  cumulative_reward_ += result.reward;
  sum_abs_cte_ += std::fabs(nav.cross_track_error);
  result.goal_reached =
      nav.goal_distance <= config_.goal_radius || nav.progress >= config_.goal_progress;
  const bool reward_floor =
      !config_.test_mode && cumulative_reward_ < config_.min_cumulative_reward;
  result.terminated = result.collision || result.goal_reached || reward_floor;
  result.truncated = steps_ >= config_.max_steps;
  if (result.terminated || result.truncated) {
    EpisodeMetrics metrics;
    metrics.progress = nav.progress;
    metrics.mean_abs_cte = sum_abs_cte_ / static_cast<double>(steps_);
    metrics.steps = steps_;
    metrics.collision = result.collision;
    metrics.goal_reached = result.goal_reached;
    metrics.truncated = result.truncated && !result.terminated;
    metrics.cumulative_reward = cumulative_reward_;
    metrics.path_length = world_.path().length();
    result.episode = metrics;
  }
  WriteObservation(observation);
  return result;
}

void Environment::WriteObservation(float* observation) {
  const VesselState& vessel = world_.vessel();
  const NavigationState& nav = world_.navigation();
  observation[0] = static_cast<float>(vessel[3]);
  observation[1] = static_cast<float>(vessel[4]);
  observation[2] = static_cast<float>(vessel[5]);
  observation[3] = static_cast<float>(nav.cross_track_error / kCteObservationScale);
  observation[4] = static_cast<float>(nav.heading_error);
  observation[5] = static_cast<float>(nav.look_ahead_heading_error);
  float* scans = observation + kNavigationSize;
  if (scan_ring_.empty()) {
    WriteCloseness(scans);
    return;
  }
  const std::int64_t slots = static_cast<std::int64_t>(scan_ring_.size()) / kNumRays;
  const auto slot = [&](std::int64_t step) {
    return scan_ring_.begin() + ((step % slots + slots) % slots) * kNumRays;
  };
  WriteCloseness(&*slot(steps_));
  if (steps_ == 0) {  // a new episode: every earlier scan is its first one
    for (std::int64_t s = 1; s < slots; ++s) std::copy_n(slot(0), kNumRays, slot(s));
  }
  for (int k = 0; k <= config_.scan_history; ++k) {
    std::copy_n(slot(steps_ - std::int64_t{k} * config_.scan_history_interval), kNumRays,
                scans + static_cast<std::ptrdiff_t>(k) * kNumRays);
  }
}

void Environment::WriteCloseness(float* closeness) const {
  const auto& ranges = world_.ranges();
  for (int i = 0; i < kNumRays; ++i) {
    closeness[i] = static_cast<float>(Closeness(ranges[i], config_.closeness));
  }
}

}  // namespace colav

#include "eval/replay/replay_recorder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "env/navigation.h"

namespace colav {
namespace {

// The smoothed path sampled this often (m): finer than a pixel at any useful zoom.
constexpr double kPathSampleSpacing = 2.0;

ReplayPoint PointOf(const Eigen::Vector2d& point) {
  return {static_cast<float>(point.x()), static_cast<float>(point.y())};
}

std::vector<ReplayPoint> PathPolyline(const Path& path) {
  const int segments = std::max(1, static_cast<int>(std::ceil(path.length() / kPathSampleSpacing)));
  std::vector<ReplayPoint> points;
  for (int i = 0; i <= segments; ++i) {
    points.push_back(PointOf(path.Point(path.length() * i / segments)));
  }
  return points;
}

std::vector<ReplayPose> MovingVesselPoses(const World& world) {
  std::vector<ReplayPose> poses;
  for (const MovingObstacle& vessel : world.moving_obstacles()) {
    poses.push_back({static_cast<float>(vessel.position().x()),
                     static_cast<float>(vessel.position().y()),
                     static_cast<float>(vessel.spec().course)});
  }
  return poses;
}

ReplayScene SceneOf(const World& world) {
  ReplayScene scene;
  scene.path = PathPolyline(world.path());
  for (const CircleSpec& circle : world.static_obstacles()) {
    scene.circles.push_back({static_cast<float>(circle.center.x()),
                             static_cast<float>(circle.center.y()),
                             static_cast<float>(circle.radius)});
  }
  for (const MovingObstacle& vessel : world.moving_obstacles()) {
    scene.vessel_widths.push_back(static_cast<float>(vessel.spec().width));
  }
  return scene;
}

// The line-of-sight target the heading error is measured to (env/navigation.cpp).
Eigen::Vector2d LookAheadPoint(const World& world) {
  const Path& path = world.path();
  return path.Point(
      std::min(path.length(), world.navigation().closest_arclength + kLookAheadDistance));
}

}  // namespace

ReplayRecorder::ReplayRecorder(const World& world, std::string scene_name, std::string label) {
  replay_.scene = SceneOf(world);
  replay_.scene.name = std::move(scene_name);
  replay_.runs.push_back({std::move(label), {}});
  const double no_action[kActionSize] = {0.0, 0.0};
  AddStep(world, no_action, 0.0);
}

void ReplayRecorder::Record(const World& world, const double* action, const StepResult& result) {
  AddStep(world, action, result.reward);
}

void ReplayRecorder::AddStep(const World& world, const double* action, double reward) {
  const VesselState& vessel = world.vessel();
  const NavigationState& nav = world.navigation();
  ReplayStep step;
  step.pose = {static_cast<float>(vessel[0]), static_cast<float>(vessel[1]),
               static_cast<float>(vessel[2])};
  step.surge = static_cast<float>(vessel[3]);
  step.sway = static_cast<float>(vessel[4]);
  step.yaw_rate = static_cast<float>(vessel[5]);
  step.cross_track_error = static_cast<float>(nav.cross_track_error);
  step.heading_error = static_cast<float>(nav.heading_error);
  step.look_ahead_heading_error = static_cast<float>(nav.look_ahead_heading_error);
  step.progress = static_cast<float>(nav.progress);
  step.look_ahead_point = PointOf(LookAheadPoint(world));
  for (int k = 0; k < kActionSize; ++k) {
    step.action[k] = static_cast<float>(std::clamp(action[k], -1.0, 1.0));  // as the vessel used it
  }
  step.reward = static_cast<float>(reward);
  step.collision = world.collision();
  for (int i = 0; i < kNumRays; ++i) step.closeness[i] = ClosenessByte(world.ranges()[i]);
  replay_.runs.front().steps.push_back(step);
  replay_.scene.vessel_poses.push_back(MovingVesselPoses(world));
}

Replay CombineRuns(std::vector<Replay> replays) {
  if (replays.empty()) throw std::invalid_argument("CombineRuns: no replay");
  const auto longest =
      std::max_element(replays.begin(), replays.end(), [](const Replay& a, const Replay& b) {
        return a.scene.vessel_poses.size() < b.scene.vessel_poses.size();
      });
  Replay combined;
  combined.scene = std::move(longest->scene);
  for (Replay& replay : replays) {
    for (ReplayRun& run : replay.runs) combined.runs.push_back(std::move(run));
  }
  return combined;
}

}  // namespace colav

#include "eval/replay/replay_json.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "eval/replay/base64.h"

namespace colav {
namespace {

constexpr int kFormat = 1;

// The per-step numbers in the order the file stores them.
const std::vector<std::string>& StepFields() {
  static const std::vector<std::string> fields = {"x",
                                                  "y",
                                                  "heading",
                                                  "surge",
                                                  "sway",
                                                  "yaw_rate",
                                                  "cross_track_error",
                                                  "heading_error",
                                                  "look_ahead_heading_error",
                                                  "progress",
                                                  "look_ahead_x",
                                                  "look_ahead_y",
                                                  "thrust_action",
                                                  "moment_action",
                                                  "reward"};
  return fields;
}

std::vector<float> StepNumbers(const ReplayStep& s) {
  return {s.pose.x,
          s.pose.y,
          s.pose.heading,
          s.surge,
          s.sway,
          s.yaw_rate,
          s.cross_track_error,
          s.heading_error,
          s.look_ahead_heading_error,
          s.progress,
          s.look_ahead_point.x,
          s.look_ahead_point.y,
          s.action[0],
          s.action[1],
          s.reward};
}

ReplayStep StepOfNumbers(const float* n) {
  ReplayStep s;
  s.pose = {n[0], n[1], n[2]};
  s.surge = n[3];
  s.sway = n[4];
  s.yaw_rate = n[5];
  s.cross_track_error = n[6];
  s.heading_error = n[7];
  s.look_ahead_heading_error = n[8];
  s.progress = n[9];
  s.look_ahead_point = {n[10], n[11]};
  s.action = {n[12], n[13]};
  s.reward = n[14];
  return s;
}

// Little-endian float32 bytes (the byte order of every machine this runs on and of the
// page's Float32Array there).
std::string FloatsBase64(const std::vector<float>& values) {
  std::vector<std::uint8_t> bytes(values.size() * sizeof(float));
  std::memcpy(bytes.data(), values.data(), bytes.size());
  return Base64Encode(bytes);
}

std::vector<float> FloatsOfBase64(const nlohmann::json& text, std::size_t group) {
  const std::vector<std::uint8_t> bytes = Base64Decode(text.get<std::string>());
  if (bytes.size() % (group * sizeof(float)) != 0) {
    throw std::invalid_argument("replay: float array of " + std::to_string(bytes.size()) +
                                " bytes is not made of groups of " + std::to_string(group));
  }
  std::vector<float> values(bytes.size() / sizeof(float));
  std::memcpy(values.data(), bytes.data(), bytes.size());
  return values;
}

nlohmann::json SceneJson(const ReplayScene& scene) {
  std::vector<float> path;
  for (const ReplayPoint& p : scene.path) path.insert(path.end(), {p.x, p.y});
  std::vector<float> circles;
  for (const ReplayCircle& c : scene.circles) circles.insert(circles.end(), {c.x, c.y, c.radius});
  std::vector<float> poses;
  for (const auto& step : scene.vessel_poses) {
    for (const ReplayPose& p : step) poses.insert(poses.end(), {p.x, p.y, p.heading});
  }
  return {{"name", scene.name},
          {"path", FloatsBase64(path)},
          {"circles", FloatsBase64(circles)},
          {"vessel_widths", scene.vessel_widths},
          {"vessel_poses", FloatsBase64(poses)}};
}

ReplayScene SceneOfJson(const nlohmann::json& document) {
  ReplayScene scene;
  scene.name = document.at("name").get<std::string>();
  const std::vector<float> path = FloatsOfBase64(document.at("path"), 2);
  for (std::size_t i = 0; i < path.size(); i += 2) scene.path.push_back({path[i], path[i + 1]});
  const std::vector<float> circles = FloatsOfBase64(document.at("circles"), 3);
  for (std::size_t i = 0; i < circles.size(); i += 3) {
    scene.circles.push_back({circles[i], circles[i + 1], circles[i + 2]});
  }
  scene.vessel_widths = document.at("vessel_widths").get<std::vector<float>>();
  const std::size_t vessels = scene.vessel_widths.size();
  const std::vector<float> poses = FloatsOfBase64(document.at("vessel_poses"), 3);
  if (vessels == 0 && !poses.empty()) throw std::invalid_argument("replay: poses of no vessel");
  const std::size_t per_step = 3 * vessels;
  for (std::size_t i = 0; vessels > 0 && i < poses.size(); i += per_step) {
    std::vector<ReplayPose> step;
    for (std::size_t k = i; k < i + per_step; k += 3) {
      step.push_back({poses[k], poses[k + 1], poses[k + 2]});
    }
    scene.vessel_poses.push_back(std::move(step));
  }
  return scene;
}

nlohmann::json RunJson(const ReplayRun& run) {
  std::vector<float> numbers;
  std::vector<std::uint8_t> closeness;
  std::vector<int> collisions;
  for (std::size_t k = 0; k < run.steps.size(); ++k) {
    const ReplayStep& step = run.steps[k];
    const std::vector<float> values = StepNumbers(step);
    numbers.insert(numbers.end(), values.begin(), values.end());
    closeness.insert(closeness.end(), step.closeness.begin(), step.closeness.end());
    if (step.collision) collisions.push_back(static_cast<int>(k));
  }
  return {{"label", run.label},
          {"steps", run.steps.size()},
          {"numbers", FloatsBase64(numbers)},
          {"closeness", Base64Encode(closeness)},
          {"collisions", collisions}};
}

ReplayRun RunOfJson(const nlohmann::json& document) {
  ReplayRun run;
  run.label = document.at("label").get<std::string>();
  const std::size_t steps = document.at("steps").get<std::size_t>();
  const std::size_t fields = StepFields().size();
  const std::vector<float> numbers = FloatsOfBase64(document.at("numbers"), fields);
  const std::vector<std::uint8_t> closeness =
      Base64Decode(document.at("closeness").get<std::string>());
  if (numbers.size() != steps * fields || closeness.size() != steps * kNumRays) {
    throw std::invalid_argument("replay: run '" + run.label + "' does not hold " +
                                std::to_string(steps) + " steps");
  }
  for (std::size_t k = 0; k < steps; ++k) {
    ReplayStep step = StepOfNumbers(&numbers[k * fields]);
    std::copy_n(&closeness[k * kNumRays], kNumRays, step.closeness.begin());
    run.steps.push_back(step);
  }
  for (const int k : document.at("collisions").get<std::vector<int>>()) {
    run.steps.at(static_cast<std::size_t>(k)).collision = true;
  }
  return run;
}

}  // namespace

nlohmann::json ReplayJson(const Replay& replay) {
  nlohmann::json document = SceneJson(replay.scene);
  document["format"] = kFormat;
  document["step_fields"] = StepFields();
  document["runs"] = nlohmann::json::array();
  for (const ReplayRun& run : replay.runs) document["runs"].push_back(RunJson(run));
  return document;
}

Replay ReplayFromJson(const nlohmann::json& document) {
  try {
    if (document.at("format").get<int>() != kFormat) {
      throw std::invalid_argument("replay: unknown format " + document.at("format").dump());
    }
    Replay replay;
    replay.scene = SceneOfJson(document);
    for (const nlohmann::json& run : document.at("runs")) replay.runs.push_back(RunOfJson(run));
    return replay;
  } catch (const nlohmann::json::exception& error) {
    throw std::invalid_argument(std::string("replay: ") + error.what());
  }
}

}  // namespace colav

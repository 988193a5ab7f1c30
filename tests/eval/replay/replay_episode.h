// An episode recorded both as a replay and as `simulate` trace rows, for the replay tests: the
// head-on scenario file driven straight ahead at full thrust until it collides.
#pragma once

#include <string>
#include <vector>

#include "env/environment.h"
#include "env/scenario_file.h"
#include "env/trace.h"
#include "eval/replay/replay_recorder.h"
#include "tests/src/project_paths.h"

namespace colav::testing_util {

struct RecordedEpisode {
  Replay replay;
  std::vector<std::string> trace_rows;  ///< TraceRow of each step, row 0 after the reset
};

inline RecordedEpisode HeadOnEpisode(double thrust = 1.0, const std::string& label = "straight") {
  const Scenario scenario =
      LoadScenarioFile(std::string(kSourceDir) + "/configs/scenarios/head-on.yaml");
  Environment env(EnvironmentConfig{}, std::make_shared<FixedScenarioSource>(scenario));
  std::vector<float> observation(kObservationSize);
  env.Reset(0, observation.data());
  ReplayRecorder recorder(env.world(), scenario.name, label);
  RecordedEpisode episode;
  episode.trace_rows.push_back(TraceRow(0, env.world(), StepResult{}));
  const double action[kActionSize] = {thrust, 0.0};
  for (std::int64_t step = 1;; ++step) {
    const StepResult result = env.Step(action, observation.data());
    recorder.Record(env.world(), action, result);
    episode.trace_rows.push_back(TraceRow(step, env.world(), result));
    if (result.terminated || result.truncated) break;
  }
  episode.replay = recorder.TakeReplay();
  return episode;
}

}  // namespace colav::testing_util

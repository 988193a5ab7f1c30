// Records an episode of one world as a replay, step by step, from the same World and StepResult a
// `simulate` trace row is written from.
#pragma once

#include <string>

#include "env/environment.h"
#include "eval/replay/replay.h"

namespace colav {

class ReplayRecorder {
 public:
  /// Starts with the world just after its reset; `label` names the run (the model).
  ReplayRecorder(const World& world, std::string scene_name, std::string label);

  /// Adds the world after a step under `action` (kActionSize values).
  void Record(const World& world, const double* action, const StepResult& result);

  const Replay& replay() const { return replay_; }
  Replay TakeReplay() { return std::move(replay_); }

 private:
  void AddStep(const World& world, const double* action, double reward);

  Replay replay_;
};

/// One replay of several runs of the same scene (e.g. models paired on a scenario): the runs in
/// order, the scene of the longest (whose moving vessels' poses cover every run).
Replay CombineRuns(std::vector<Replay> replays);

}  // namespace colav

// The run folder's training logs: episodes.csv (one row per finished episode) and updates.csv
// (one row per PPO update, with Stable-Baselines3's metric names), plus the rolling statistics of
// the last 100 episodes shown by the progress display.
//
// Rows are appended as they come and flushed at every checkpoint; a resumed run keeps the rows
// written before its checkpoint's rollout start and drops the rest (and any torn last line), since
// it replays those steps. The rows it keeps are checked: a damaged file is a UserError naming it.
#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <fstream>
#include <optional>

#include "train/ppo/rollout.h"
#include "train/ppo/update.h"

namespace colav {

/// Means over the last (up to) 100 finished episodes.
struct RollingEpisodeStats {
  int count = 0;
  double reward = 0.0;
  double progress = 0.0;
  double mean_cte = 0.0;  ///< m
  double steps = 0.0;
  double collision_rate = 0.0;
  double goal_rate = 0.0;
};

/// Timing of one rollout and its update.
struct IterationTiming {
  double fps = 0.0;  ///< environment steps per second of wall time since the session started
  double rollout_s = 0.0;
  double update_s = 0.0;
};

/// The rows a resumed run keeps: those its checkpoint's rollout start had written.
struct KeptLogRows {
  std::int64_t episodes = 0;   ///< rows of episodes.csv
  std::int64_t updates = 0;    ///< rows of updates.csv
  std::int64_t last_step = 0;  ///< no kept row is of a later global_step
};

class TrainingLogs {
 public:
  /// Opens the CSVs in run_dir: new ones, or with `resume`, the kept rows of the existing ones.
  TrainingLogs(const std::filesystem::path& run_dir, std::optional<KeptLogRows> resume);

  void AddEpisode(std::int64_t global_step, const FinishedEpisode& episode);
  void AddUpdate(std::int64_t global_step, const UpdateStats& stats, const IterationTiming& timing);
  void Flush();

  RollingEpisodeStats Rolling() const;

 private:
  struct EpisodeSummary {
    double reward, progress, mean_cte, steps;
    bool collision, goal;
  };
  void Remember(const EpisodeSummary& episode);

  std::ofstream episodes_;
  std::ofstream updates_;
  std::deque<EpisodeSummary> window_;
};

}  // namespace colav

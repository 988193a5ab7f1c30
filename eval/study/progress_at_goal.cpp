#include "eval/study/progress_at_goal.h"

#include <string>

namespace colav {
namespace {

// Pairs compared and A's wins (ties half) in one part of the split.
struct Tally {
  double pairs = 0.0;
  double wins = 0.0;

  void Add(double a, double b) {
    pairs += 1.0;
    wins += a > b ? 1.0 : a == b ? 0.5 : 0.0;
  }
  double Probability() const { return pairs > 0.0 ? wins / pairs : 0.5; }
};

}  // namespace

ProgressAtGoalSplit SplitProgressAtGoal(const std::vector<const ModelEpisodes*>& a,
                                        const std::vector<const ModelEpisodes*>& b) {
  Tally both_at_goal;
  Tally elsewhere;
  for (const ModelEpisodes* seed_a : a) {
    for (const ModelEpisodes* seed_b : b) {
      const std::vector<double>& progress_a = seed_a->at("progress");
      const std::vector<double>& progress_b = seed_b->at("progress");
      const std::vector<double>& goal_a = seed_a->at("goal");
      const std::vector<double>& goal_b = seed_b->at("goal");
      for (std::size_t s = 0; s < progress_a.size(); ++s) {
        Tally& part = goal_a[s] > 0.0 && goal_b[s] > 0.0 ? both_at_goal : elsewhere;
        part.Add(progress_a[s], progress_b[s]);
      }
    }
  }
  const double pairs = both_at_goal.pairs + elsewhere.pairs;
  return {pairs > 0.0 ? both_at_goal.pairs / pairs : 0.0, both_at_goal.Probability(),
          elsewhere.Probability()};
}

SeedScores ProgressToFinish(const std::vector<const ModelEpisodes*>& seeds) {
  constexpr double kFinish = 100.0;  // %, as the study's progress
  SeedScores scores;
  for (const ModelEpisodes* seed : seeds) {
    const std::vector<double>& progress = seed->at("progress");
    const std::vector<double>& goal = seed->at("goal");
    std::vector<double>& finish = scores.emplace_back(progress);
    for (std::size_t s = 0; s < finish.size(); ++s) {
      if (goal[s] > 0.0) finish[s] = kFinish;
    }
  }
  return scores;
}

}  // namespace colav

// Aggregates over training seeds, the way rliable (Agarwal et al., NeurIPS 2021) reports deep-RL
// results: the interquartile mean, and the probability of improvement of one configuration over
// another with a bootstrap confidence interval.
//
// Scores are arranged [seed][scenario]; all seeds of a configuration play the same scenarios
// (paired evaluation), and higher scores are better (negate a metric where lower is better).
#pragma once

#include <cstdint>
#include <vector>

#include "src/rate_interval.h"

namespace colav {

/// scores[seed][scenario]: every seed has the same number of scenarios.
using SeedScores = std::vector<std::vector<double>>;

/// Interquartile mean: the mean of the values left after removing the lowest and highest
/// floor(n / 4) values (scipy.stats.trim_mean(values, 0.25), rliable's IQM). Not empty.
double InterquartileMean(std::vector<double> values);

/// P(A better than B): over scenarios t and seed pairs (i, j), the mean of S(a[i][t], b[j][t])
/// with S = 1 when a > b, 1/2 when equal, 0 otherwise (the Mann-Whitney U statistic per scenario,
/// averaged over scenarios, as rliable's probability of improvement).
double ProbabilityOfImprovement(const SeedScores& a, const SeedScores& b);

struct ImprovementEstimate {
  double probability = 0.0;
  Interval ci;  ///< percentile bootstrap interval at the requested level
};

/// ProbabilityOfImprovement with a percentile bootstrap interval. Each resample draws the seeds
/// of A and of B with replacement, each seed keeping all its scenarios (a seed is one training
/// run that plays every scenario, so its scenarios are not independent draws), and, with
/// resample_scenarios, the scenarios too. rliable stratifies by task instead (runs resampled
/// within each task), which fits tasks trained separately but would treat one agent's 1,000
/// scenarios as 1,000 independent runs here and understate the spread between seeds.
ImprovementEstimate ProbabilityOfImprovementInterval(const SeedScores& a, const SeedScores& b,
                                                     std::uint64_t seed, int resamples = 2000,
                                                     double level = 0.95,
                                                     bool resample_scenarios = true);

}  // namespace colav

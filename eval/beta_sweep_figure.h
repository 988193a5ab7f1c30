// The beta sweep of the paper: final test metrics of agents whose locked encoder was pre-trained
// with different beta, against beta (means with their 95 % CIs as error bars), and its table.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "eval/evaluation_summary.h"

namespace colav {

struct BetaSweepPoint {
  double beta = 0.0;
  ModelSummary model;  ///< the agent's evaluation summary
};

/// Four panels (progress, cross-track error, duration, collisions) against beta, points sorted by
/// beta, to `png`.
void PlotBetaSweep(std::vector<BetaSweepPoint> points, const std::string& title,
                   const std::filesystem::path& png);

/// Markdown table: one row per beta (ascending), "mean [95 % CI]" per metric.
std::string BetaSweepTable(std::vector<BetaSweepPoint> points);

}  // namespace colav

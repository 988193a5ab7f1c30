// Where a scan of the VAE dataset comes from; stored as the `group` column of the dataset file.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace colav {

enum class ScanGroup : std::int64_t {
  kSimulator = 0,         ///< recorded in the training environment under the scripted pilot
  kSyntheticMixed = 1,    ///< synthetic: 3 circles + 2 vessels
  kSyntheticVessels = 2,  ///< synthetic: 5 vessels
  kSyntheticCircles = 3,  ///< synthetic: 5 circles
};
inline constexpr int kNumScanGroups = 4;

/// The synthetic groups in the order their scans are generated and stored.
inline constexpr std::array<ScanGroup, 3> kSyntheticGroups = {
    ScanGroup::kSyntheticMixed, ScanGroup::kSyntheticVessels, ScanGroup::kSyntheticCircles};

/// Obstacles in a synthetic scene of a group (reference-learning 5).
struct SyntheticObstacleCounts {
  int circles = 0;
  int vessels = 0;
};
SyntheticObstacleCounts ObstacleCountsOf(ScanGroup group);

/// "simulator", "synthetic 3 circles + 2 vessels", ...
std::string ScanGroupName(ScanGroup group);

}  // namespace colav

#include "train/dataset/scan_group.h"

#include <stdexcept>

namespace colav {

SyntheticObstacleCounts ObstacleCountsOf(ScanGroup group) {
  switch (group) {
    case ScanGroup::kSyntheticMixed:
      return {3, 2};
    case ScanGroup::kSyntheticVessels:
      return {0, 5};
    case ScanGroup::kSyntheticCircles:
      return {5, 0};
    case ScanGroup::kSimulator:
      break;
  }
  throw std::invalid_argument("ObstacleCountsOf: not a synthetic group");
}

std::string ScanGroupName(ScanGroup group) {
  switch (group) {
    case ScanGroup::kSimulator:
      return "simulator";
    case ScanGroup::kSyntheticMixed:
      return "synthetic 3 circles + 2 vessels";
    case ScanGroup::kSyntheticVessels:
      return "synthetic 5 vessels";
    case ScanGroup::kSyntheticCircles:
      return "synthetic 5 circles";
  }
  throw std::invalid_argument("ScanGroupName: unknown group");
}

}  // namespace colav

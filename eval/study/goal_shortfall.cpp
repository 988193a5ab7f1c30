#include "eval/study/goal_shortfall.h"

#include <algorithm>
#include <cmath>

#include "eval/study/study_metrics.h"

namespace colav {
namespace {

// Totals closer than this are a tie: sums of the same means in another order differ by rounding.
constexpr double kTieTolerance = 1e-9;

int NetworksOf(const StudySpec& spec, const std::string& model) {
  const EnsembleSpec* ensemble = spec.FindEnsemble(model);
  return ensemble ? static_cast<int>(ensemble->members.size()) : 1;
}

}  // namespace

std::vector<GoalShortfall> MeasureGoalShortfalls(const StudySpec& spec,
                                                 const ScenarioSetReport& report) {
  std::vector<GoalShortfall> shortfalls;
  for (const SeededModel& seeded : spec.SeededModels()) {
    const ModelSummary& summary = SummaryOf(report, seeded.name);
    GoalShortfall shortfall{seeded.name, NetworksOf(spec, seeded.name), {}, 0.0};
    for (const auto& [name, bound] : spec.evaluation.goal) {
      const double mean = summary.metrics.at(name).mean;
      const double short_by = FindStudyMetric(name)->higher_is_better ? bound - mean : mean - bound;
      shortfall.by_metric[name] = std::max(0.0, short_by);
      shortfall.total += shortfall.by_metric[name];
    }
    shortfalls.push_back(shortfall);
  }
  return shortfalls;
}

const GoalShortfall& ChooseByShortfall(const std::vector<GoalShortfall>& shortfalls) {
  const GoalShortfall* chosen = &shortfalls.front();
  for (const GoalShortfall& candidate : shortfalls) {
    const bool smaller = candidate.total < chosen->total - kTieTolerance;
    const bool tie = std::abs(candidate.total - chosen->total) <= kTieTolerance;
    if (smaller || (tie && candidate.networks < chosen->networks)) chosen = &candidate;
  }
  return *chosen;
}

}  // namespace colav

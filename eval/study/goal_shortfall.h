// How far each model's means fall short of a study's goal (evaluation.goal: a bound per metric),
// and the model a set of scenarios chooses by it. Applied to validation scenarios, it is the
// choice a study file fixes before any run, so that only the chosen model's test figures are a
// claim.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "eval/study/study_report.h"
#include "eval/study/study_spec.h"

namespace colav {

struct GoalShortfall {
  std::string model;
  int networks = 1;                         ///< runs acting together: an ensemble's members
  std::map<std::string, double> by_metric;  ///< per bound, how far the mean falls short (>= 0)
  double total = 0.0;                       ///< their sum, in the report's units (points, metres)

  bool met() const { return total == 0.0; }
};

/// Every model the study trains or combines (StudySpec::SeededModels, in file order) against
/// `spec.evaluation.goal`, from its means in `report`.
std::vector<GoalShortfall> MeasureGoalShortfalls(const StudySpec& spec,
                                                 const ScenarioSetReport& report);

/// The model of the smallest total shortfall; ties to fewer networks, then to the first in file
/// order. `shortfalls` must not be empty.
const GoalShortfall& ChooseByShortfall(const std::vector<GoalShortfall>& shortfalls);

}  // namespace colav

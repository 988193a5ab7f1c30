// What averaging runs' actions changes (study_spec.h, EnsembleSpec): each ensemble's mean minus
// the mean of its own members' means, per metric, on the same scenarios. The kind's comparison
// with other configurations mixes two effects: which runs it holds and that it averages them.
// Against its own members only the averaging remains. Over the kind's ensembles (which share no
// run): the mean difference with a Student-t interval; none for a kind of one ensemble.
#pragma once

#include <map>
#include <string>

#include "eval/study/study_results.h"
#include "src/statistics.h"

namespace colav {

struct EnsembleGain {
  std::string ensemble;  ///< the kind's name
  /// By StudyMetric::name, every StudyMetrics(), in the report's units (points for % metrics).
  std::map<std::string, MeanConfidenceInterval> metrics;
};

/// The gain of the kind `ensemble` from the episodes of its ensembles ("<kind>.seed_<k>") and of
/// the runs they hold ("<config>.seed_<seed>"), all in `results`.
EnsembleGain MeasureEnsembleGain(const EnsembleSpec& ensemble, const ScenarioSetResults& results);

}  // namespace colav

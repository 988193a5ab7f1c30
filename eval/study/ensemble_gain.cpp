#include "eval/study/ensemble_gain.h"

#include <vector>

namespace colav {

EnsembleGain MeasureEnsembleGain(const EnsembleSpec& ensemble, const ScenarioSetResults& results) {
  EnsembleGain gain{ensemble.name, {}};
  for (const StudyMetric& metric : StudyMetrics()) {
    std::vector<double> differences;
    for (int k = 0; k < ensemble.count; ++k) {
      std::vector<double> member_means;
      for (std::size_t i = 0; i < ensemble.members.size(); ++i) {
        const std::string member = SeedModelName(ensemble.members[i], ensemble.MemberSeed(i, k));
        member_means.push_back(Mean(results.models.at(member).at(metric.name)));
      }
      const ModelEpisodes& own = results.models.at(SeedModelName(ensemble.name, k));
      differences.push_back(Mean(own.at(metric.name)) - Mean(member_means));
    }
    gain.metrics[metric.name] = Summarise(differences);
  }
  return gain;
}

}  // namespace colav

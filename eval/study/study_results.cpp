#include "eval/study/study_results.h"

#include "src/csv_table.h"
#include "src/error.h"

namespace colav {

std::map<std::string, ScenarioSetResults> ReadStudyResults(const StudySpec& spec,
                                                           const std::filesystem::path& out) {
  std::map<std::string, ScenarioSetResults> sets;
  for (const EvaluationGroup& group : EvaluationGroups(spec, out)) {
    const std::filesystem::path file = out / "eval" / group.scenario_set / "episodes.csv";
    const CsvTable table = ReadCsvTable(file);
    ScenarioSetResults& results = sets[group.scenario_set];
    results.episodes = group.episodes;
    results.seed = group.seed;
    std::map<std::string, std::vector<double>> columns;
    for (const StudyMetric& metric : StudyMetrics()) {
      columns[metric.name] = NumericColumn(table, metric.column);
    }
    const std::size_t model_column = 0;  // episodes.csv: model,scenario,seed,...
    for (std::size_t row = 0; row < table.rows.size(); ++row) {
      ModelEpisodes& model = results.models[table.rows[row][model_column]];
      for (const StudyMetric& metric : StudyMetrics()) {
        model[metric.name].push_back(columns[metric.name][row] * metric.scale);
      }
    }
    for (const std::string& name : group.models) {
      const auto model = results.models.find(name);
      if (model == results.models.end() ||
          static_cast<int>(model->second.at("progress").size()) != group.episodes) {
        throw UserError(file.string() + ": no complete results for model '" + name + "'");
      }
    }
  }
  return sets;
}

}  // namespace colav

#include "eval/study/run_diagnostics.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "src/csv_table.h"
#include "src/error.h"

namespace colav {
namespace {

// A number of the run's summary.json; UserError naming the file and key otherwise.
double SummaryNumber(const std::filesystem::path& file, const char* key) {
  std::ifstream in(file);
  if (!in) throw UserError(file.string() + ": cannot read the run's summary");
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (summary.is_discarded() || !summary.contains(key) || !summary[key].is_number()) {
    throw UserError(file.string() + ": no number '" + key + "'");
  }
  return summary[key].get<double>();
}

// The last value of a column; UserError naming the file when it has no row.
double LastValue(const CsvTable& table, const std::string& column) {
  const std::vector<double> values = NumericColumn(table, column);
  if (values.empty()) throw UserError(table.path.string() + ": no rows");
  return values.back();
}

}  // namespace

RunDiagnostics ReadRunDiagnostics(const std::filesystem::path& run) {
  RunDiagnostics diagnostics;
  diagnostics.wall_s = SummaryNumber(run / "summary.json", "total_wall_s");
  diagnostics.final_std = LastValue(ReadCsvTable(run / "updates.csv"), "std");
  const CsvTable episodes = ReadCsvTable(run / "episodes.csv");
  const std::vector<double> steps = NumericColumn(episodes, "global_step");
  const std::vector<double> collisions = NumericColumn(episodes, "collision");
  const std::vector<double> time_outs = NumericColumn(episodes, "truncated");
  if (steps.empty()) throw UserError(episodes.path.string() + ": no episodes");
  const double late = kLateShare * steps.back();
  int collided = 0;
  int timed_out = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i] <= late) continue;
    ++diagnostics.late_episodes;
    collided += collisions[i] > 0.0 ? 1 : 0;
    timed_out += time_outs[i] > 0.0 ? 1 : 0;
  }
  diagnostics.late_collisions = 100.0 * collided / diagnostics.late_episodes;
  diagnostics.late_time_outs = 100.0 * timed_out / diagnostics.late_episodes;
  return diagnostics;
}

}  // namespace colav

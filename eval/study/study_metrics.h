// The metrics a study reports on every model: their units and which way is better.
#pragma once

#include <string>
#include <vector>

namespace colav {

/// What the report measures, one column of evaluate's episodes.csv each.
struct StudyMetric {
  std::string name;    ///< key in summary.json: "progress", "collision", ...
  std::string column;  ///< column of episodes.csv
  std::string label;   ///< table heading
  double scale;        ///< 100 for fractions shown as %
  bool higher_is_better;
  bool is_rate;  ///< 0/1 per episode: Wilson intervals

  /// Progress and the rates: their intervals must stay inside [0, scale].
  bool bounded() const { return is_rate || name == "progress"; }
};

/// progress, cross_track_error, duration, collision, goal, time_out, return.
const std::vector<StudyMetric>& StudyMetrics();

/// The metric named `name`, nullptr when the report has none of that name.
const StudyMetric* FindStudyMetric(const std::string& name);

}  // namespace colav

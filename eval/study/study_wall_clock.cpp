#include "eval/study/study_wall_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <string>

#include "eval/study/process_identity.h"
#include "src/atomic_file.h"
#include "src/progress.h"

namespace colav {
namespace {

std::filesystem::path SpanFolder(const std::filesystem::path& folder) {
  return folder / "wall_clock";
}

std::vector<WallClockSpan> ReadSpans(const std::filesystem::path& folder) {
  std::vector<WallClockSpan> spans;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(SpanFolder(folder), error)) {
    if (entry.path().extension() != ".tsv") continue;
    std::ifstream in(entry.path());
    WallClockSpan span;
    if (in >> span.first >> span.second && span.second >= span.first) spans.push_back(span);
  }
  return spans;
}

// The sum of the durations in the one-number-per-line file of the runner before spans.
double LegacyDurations(const std::filesystem::path& folder) {
  std::ifstream in(folder / "wall_clock.tsv");
  double total = 0.0;
  for (double duration = 0.0; in >> duration;) total += duration;
  return total;
}

}  // namespace

void RecordWallClockSpan(const std::filesystem::path& folder, const WallClockSpan& span) {
  const ProcessIdentity self = CurrentProcess();
  const std::string name = Fixed(span.first, 3) + "-" + self.host + "-" + std::to_string(self.pid);
  WriteTextFileAtomically(SpanFolder(folder) / (name + ".tsv"),
                          Fixed(span.first, 3) + "\t" + Fixed(span.second, 3) + "\n");
}

double CoveredSeconds(std::vector<WallClockSpan> spans) {
  std::sort(spans.begin(), spans.end());
  double covered = 0.0;
  double reached = -1e300;  // the end of the spans counted so far
  for (const auto& [start, end] : spans) {
    const double from = std::max(start, reached);
    if (end > from) covered += end - from;
    reached = std::max(reached, end);
  }
  return covered;
}

double StudyWallClock(const std::filesystem::path& folder) {
  const double seconds = CoveredSeconds(ReadSpans(folder)) + LegacyDurations(folder);
  return std::round(seconds * 10.0) / 10.0;  // tenths, as the report and summary.json show it
}

double UnixSeconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace colav

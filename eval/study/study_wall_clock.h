// The study's wall-clock over all its invocations: each invocation (each rank of a launch) that
// ran jobs records its span from start to end; spans that overlap (ranks running at once) count
// once, so the figure is the time the study was being worked on, whatever the number of ranks.
#pragma once

#include <filesystem>
#include <utility>
#include <vector>

namespace colav {

/// [start, end] in seconds since the Unix epoch.
using WallClockSpan = std::pair<double, double>;

/// Records one invocation's span as its own file under FOLDER/wall_clock/ (written atomically;
/// ranks never write the same file).
void RecordWallClockSpan(const std::filesystem::path& folder, const WallClockSpan& span);

/// Seconds covered by the union of `spans`.
double CoveredSeconds(std::vector<WallClockSpan> spans);

/// The study's wall-clock in seconds, to a tenth: the union of the recorded spans, plus the
/// durations an older runner listed in FOLDER/wall_clock.tsv (one number per line).
double StudyWallClock(const std::filesystem::path& folder);

/// Now, in seconds since the Unix epoch.
double UnixSeconds();

}  // namespace colav

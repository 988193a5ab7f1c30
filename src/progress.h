// A one-line progress display for long loops (dataset generation, VAE epochs, PPO steps).
//
// On a terminal the line is redrawn in place at most ~10 times a second; elsewhere (CI, pipes,
// log files) a plain line is printed every few seconds, so logs stay readable.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace colav {

using ProgressMetrics = std::vector<std::pair<std::string, std::string>>;

/// What one progress line shows.
struct ProgressState {
  std::string label;
  std::int64_t done = 0;
  std::int64_t total = 0;  // <= 0: unknown, no bar, percentage or ETA
  std::string unit;
  double elapsed_s = 0.0;
  double rate = 0.0;  // units per second
  ProgressMetrics metrics;
};

/// "MM:SS", or "H:MM:SS" from an hour on; "--:--" for negative or non-finite durations.
std::string FormatDuration(double seconds);
/// `value` with `digits` digits after the point (printf's "%.*f").
std::string Fixed(double value, int digits);
/// Seconds from `start` to now.
double SecondsSince(std::chrono::steady_clock::time_point start);
/// "0.52 steps/s", "812 steps/s", "12.3k steps/s", "4.5M steps/s".
std::string FormatRate(double per_second, const std::string& unit);
/// The progress line: label, bar (if bar_width > 0 and the total is known), count, percentage,
/// rate, elapsed, ETA and the metrics as name=value.
std::string FormatProgressLine(const ProgressState& state, int bar_width);

struct ProgressOptions {
  bool interactive;               // redraw in place; default: stderr is a terminal
  double plain_interval_s = 10;   // seconds between plain lines when not interactive
  std::int64_t initial_done = 0;  // count already done when the bar starts (resumed runs)
  std::function<double()> clock;  // seconds; default: a steady clock
  std::ostream* out;              // default: std::cerr
  ProgressOptions();
};

class ProgressBar {
 public:
  ProgressBar(std::string label, std::int64_t total, std::string unit,
              ProgressOptions options = ProgressOptions());
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  ~ProgressBar();

  /// Records that `done` units are complete; draws if it is time to.
  void Update(std::int64_t done, const ProgressMetrics& metrics = {});
  /// Draws the final state and ends the line; later calls do nothing.
  void Finish();

 private:
  ProgressState State() const;
  void Draw(bool final_line);

  std::string label_;
  std::int64_t total_;
  std::string unit_;
  ProgressOptions options_;
  double start_s_;
  double last_draw_s_;
  std::int64_t done_;
  ProgressMetrics metrics_;
  bool finished_ = false;
};

}  // namespace colav

#include "src/progress.h"

#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace colav {
namespace {

constexpr int kBarWidth = 30;
constexpr double kRedrawInterval_s = 0.1;

double SteadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Width of the terminal on stderr, 0 when unknown: longer lines would wrap and break the redraw.
std::size_t TerminalColumns() {
  winsize size{};
  return ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 ? size.ws_col : 0;
}

}  // namespace

std::string FormatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--";
  const auto total = static_cast<std::int64_t>(seconds);
  const std::int64_t hours = total / 3600;
  const std::int64_t minutes = total / 60 % 60;
  if (hours > 0) return fmt::format("{}:{:02}:{:02}", hours, minutes, total % 60);
  return fmt::format("{:02}:{:02}", minutes, total % 60);
}

std::string Fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string FormatRate(double per_second, const std::string& unit) {
  const std::string suffix = " " + unit + "/s";
  if (per_second >= 1e6) return fmt::format("{:.1f}M", per_second / 1e6) + suffix;
  if (per_second >= 1e4) return fmt::format("{:.1f}k", per_second / 1e3) + suffix;
  if (per_second >= 100) return fmt::format("{:.0f}", per_second) + suffix;
  if (per_second >= 10) return fmt::format("{:.1f}", per_second) + suffix;
  return fmt::format("{:.2f}", per_second) + suffix;
}

std::string FormatProgressLine(const ProgressState& state, int bar_width) {
  const bool known_total = state.total > 0;
  std::string line = state.label;
  if (known_total) {
    const double fraction = std::clamp(static_cast<double>(state.done) / state.total, 0.0, 1.0);
    if (bar_width > 0) {
      const auto filled = static_cast<int>(fraction * bar_width);
      line += " [" + std::string(filled, '#') + std::string(bar_width - filled, '-') + "]";
    }
    line += fmt::format(" {}/{} {} {:.1f}%", state.done, state.total, state.unit, 100 * fraction);
  } else {
    line += fmt::format(" {} {}", state.done, state.unit);
  }
  line +=
      "  " + FormatRate(state.rate, state.unit) + "  elapsed " + FormatDuration(state.elapsed_s);
  if (known_total) {
    const double remaining_s = state.rate > 0 ? (state.total - state.done) / state.rate : -1.0;
    line += "  ETA " + FormatDuration(remaining_s);
  }
  for (const auto& [name, value] : state.metrics) line += fmt::format("  {}={}", name, value);
  return line;
}

ProgressOptions::ProgressOptions()
    : interactive(isatty(STDERR_FILENO) != 0), clock(SteadySeconds), out(&std::cerr) {}

ProgressBar::ProgressBar(std::string label, std::int64_t total, std::string unit,
                         ProgressOptions options)
    : label_(std::move(label)),
      total_(total),
      unit_(std::move(unit)),
      options_(std::move(options)),
      start_s_(options_.clock()),
      last_draw_s_(start_s_),
      done_(options_.initial_done) {}

ProgressBar::~ProgressBar() { Finish(); }

void ProgressBar::Update(std::int64_t done, const ProgressMetrics& metrics) {
  done_ = done;
  if (!metrics.empty()) metrics_ = metrics;  // metrics usually change less often than the count
  const double interval_s = options_.interactive ? kRedrawInterval_s : options_.plain_interval_s;
  if (!finished_ && options_.clock() - last_draw_s_ >= interval_s) Draw(false);
}

void ProgressBar::Finish() {
  if (finished_) return;
  Draw(true);
  finished_ = true;
}

ProgressState ProgressBar::State() const {
  ProgressState state;
  state.label = label_;
  state.done = done_;
  state.total = total_;
  state.unit = unit_;
  state.elapsed_s = options_.clock() - start_s_;
  if (state.elapsed_s > 0) state.rate = (done_ - options_.initial_done) / state.elapsed_s;
  state.metrics = metrics_;
  return state;
}

void ProgressBar::Draw(bool final_line) {
  last_draw_s_ = options_.clock();
  std::ostream& out = *options_.out;
  if (!options_.interactive) {
    out << FormatProgressLine(State(), 0) << '\n' << std::flush;
    return;
  }
  std::string line = FormatProgressLine(State(), kBarWidth);
  const std::size_t columns = TerminalColumns();
  if (columns > 1 && line.size() >= columns) line.resize(columns - 1);
  out << '\r' << line << "\033[K" << (final_line ? "\n" : "") << std::flush;
}

}  // namespace colav

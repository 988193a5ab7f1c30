#include "env/trace.h"

#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "src/error.h"
#include "src/number_text.h"

namespace colav {
namespace {

void AppendNumber(std::string& out, double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, ",%.12g", value);
  out += buffer;
}

// At most 4 decimals, trailing zeros stripped (150 stays "150").
void AppendRange(std::string& out, double range) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", range);
  std::string text = buffer;
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  out += ',';
  out += text;
}

// `text` without the spaces around it ("0.5, -1" has a space after the comma).
std::string Trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

}  // namespace

std::string TraceHeader() {
  std::string header =
      "step,x,y,psi,u,v,r,cte,heading_error,look_ahead_heading_error,progress,reward,"
      "terminated,truncated,collision";
  for (int i = 0; i < kNumRays; ++i) header += ",range_" + std::to_string(i);
  return header;
}

std::string TraceRow(std::int64_t step, const World& world, const StepResult& result) {
  std::string row = std::to_string(step);
  const VesselState& vessel = world.vessel();
  for (int k = 0; k < 6; ++k) AppendNumber(row, vessel[k]);
  const NavigationState& nav = world.navigation();
  for (const double value : {nav.cross_track_error, nav.heading_error, nav.look_ahead_heading_error,
                             nav.progress, result.reward}) {
    AppendNumber(row, value);
  }
  for (const bool flag : {result.terminated, result.truncated, world.collision()}) {
    row += flag ? ",1" : ",0";
  }
  for (const double range : world.ranges()) AppendRange(row, range);
  return row;
}

std::vector<std::array<double, kActionSize>> LoadActionsFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw UserError(path.string() + ": cannot open actions file");
  std::string line;
  if (!std::getline(in, line) || line.rfind("a0,a1", 0) != 0) {
    throw UserError(path.string() + ": line 1: expected the header 'a0,a1'");
  }
  std::vector<std::array<double, kActionSize>> actions;
  for (int number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::size_t comma = line.find(',');
    const std::optional<double> a0 = ParseFiniteNumber(Trimmed(line.substr(0, comma)));
    const std::optional<double> a1 = comma == std::string::npos
                                         ? std::nullopt
                                         : ParseFiniteNumber(Trimmed(line.substr(comma + 1)));
    if (!a0 || !a1) {
      throw UserError(path.string() + ": line " + std::to_string(number) +
                      ": expected two finite numbers 'a0,a1', got '" + line + "'");
    }
    actions.push_back({*a0, *a1});
  }
  return actions;
}

}  // namespace colav

// Per-step traces in the `simulate` format (shared/spec/interfaces.md) and action files.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "env/environment.h"
#include "env/environment_spec.h"

namespace colav {

/// Header line of a trace (no newline).
std::string TraceHeader();

/// One trace row for the world's current state; reward and flags of the step that led to it.
std::string TraceRow(std::int64_t step, const World& world, const StepResult& result);

/// Reads an actions file (header a0,a1, then one row per step); UserError with the file and
/// line on any malformed row.
std::vector<std::array<double, kActionSize>> LoadActionsFile(const std::filesystem::path& path);

}  // namespace colav

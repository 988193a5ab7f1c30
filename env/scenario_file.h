// Scenario files (YAML, shared/spec/interfaces.md): reading with validation, and writing.
#pragma once

#include <filesystem>
#include <string>

#include "env/scenario.h"

namespace colav {

/// Reads and validates a scenario file; UserError naming the file and key on any problem (missing,
/// unknown or duplicate key, wrong type, a number that is not finite or outside its plausible
/// range, such as a start faster than the vessel model integrates or a path over 100 km).
Scenario LoadScenarioFile(const std::filesystem::path& path);

/// The scenario as scenario-file YAML (full double precision).
std::string ScenarioToYaml(const Scenario& scenario);

/// A source that always yields the same scenario (the seed is ignored).
class FixedScenarioSource : public ScenarioSource {
 public:
  explicit FixedScenarioSource(Scenario scenario) : scenario_(std::move(scenario)) {}
  Scenario Make(std::uint64_t /*seed*/) const override { return scenario_; }

 private:
  Scenario scenario_;
};

}  // namespace colav

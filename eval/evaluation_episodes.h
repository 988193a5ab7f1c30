// The episodes an evaluation runs: the shared test scenarios, scenario files, and perturbed
// starts of a scenario for the trajectory figures.
//
// The test scenarios are worlds of the paper's training environment generated from a fixed list of
// seeds derived from one master seed, so every model meets exactly the same 100 worlds and models
// can be compared episode by episode (the reference drew unseeded, unshared test worlds).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "env/batched_environment.h"
#include "env/scenario.h"

namespace colav {

struct EvaluationEpisode {
  std::string name;                   ///< unique within an evaluation (tables, figure names)
  std::optional<std::uint64_t> seed;  ///< the scenario's seed; none for a scenario file
  Scenario scenario;
};

/// Test scenarios 0 .. count-1 ("test-000", ...), training worlds of TestScenarioSeed
/// (env/batched_environment.h).
std::vector<EvaluationEpisode> TestEpisodes(std::uint64_t master_seed, int count);

/// One episode per scenario file, named by the file's `name` (else its file name without
/// extension). A bad file, or two files of the same name, is a UserError naming the file.
std::vector<EvaluationEpisode> ScenarioFileEpisodes(
    const std::vector<std::filesystem::path>& files);

/// The episode with the vessel started elsewhere, as the training environment perturbs it:
/// position p(0) + U(-25, 25) per axis, heading = path direction + U(-pi, pi), at rest. Start
/// `index` (>= 1) of the episode draws from DeriveSeed(master_seed, "trajectory-start", index)
/// mixed with the episode's name, so the same starts come back on every run. Named
/// "<name>-start<index>".
EvaluationEpisode WithPerturbedStart(const EvaluationEpisode& episode, std::uint64_t master_seed,
                                     int index);

}  // namespace colav

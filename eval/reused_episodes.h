// Episodes an earlier evaluation already ran, taken instead of running them again (evaluate
// --reuse): a study that gains models evaluates only the new ones. A model's episodes depend only
// on its policy (file and sidecar), the evaluation's settings, the code that runs it and the
// scenarios, not on the other models it runs beside (eval/episode_runner.h), and episodes.csv
// keeps every value at full precision, so the taken episodes are those a new run would give, to
// the bit.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "env/environment_spec.h"
#include "eval/evaluation_episodes.h"
#include "src/config.h"

namespace colav {

struct ReusableEpisodes {
  /// Model name -> its episodes' metrics, in the order of the scenarios asked for.
  std::map<std::string, std::vector<EpisodeMetrics>> by_model;
  /// Why nothing can be taken, for the log, when by_model is empty.
  std::string why_none;
};

/// An evaluation about to run: its settings (`config`, read with `schema`; `free_keys` change no
/// episode), the build of evaluate that runs it (ProgramBuildId, src/build_id.h: the simulator's
/// and the evaluation's code) and its test scenarios.
struct PlannedEvaluation {
  const Config& config;
  const ConfigSchema& schema;
  const std::vector<std::string>& free_keys;
  std::string build_id;
  const std::vector<EvaluationEpisode>& episodes;
};

/// What the earlier evaluation in `folder` (config.yaml, summary.json, episodes.csv) offers
/// `planned`: nothing unless it ran under the same settings (free keys aside), by the same build
/// (summary.json's evaluator_build_id), on exactly these scenarios (names and seeds, in order);
/// then the episodes of each model named in `fingerprints` (model name -> PolicyFingerprint)
/// whose recorded policy_fingerprint is the same. A folder without an evaluation, or with files
/// that cannot be read, offers nothing and says why.
ReusableEpisodes FindReusableEpisodes(const std::filesystem::path& folder,
                                      const PlannedEvaluation& planned,
                                      const std::map<std::string, std::string>& fingerprints);

}  // namespace colav

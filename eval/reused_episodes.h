// Episodes an earlier evaluation already ran, taken instead of running them again (evaluate
// --reuse): a study that gains models evaluates only the new ones. A model's episodes depend only
// on its policy (file and sidecar), the evaluation's settings and the scenarios, not on the other
// models it runs beside (eval/episode_runner.h), and episodes.csv keeps every value at full
// precision, so the taken episodes are those a new run would give, to the bit.
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

/// What the earlier evaluation in `folder` (config.yaml, summary.json, episodes.csv) offers a new
/// one of the test scenarios `episodes` under `config`: nothing unless its configuration (read
/// with `schema`) equals `config` (`free_keys`, settings that change no episode, aside) and it ran
/// exactly these scenarios (names and seeds, in order); then the episodes of each model named in
/// `fingerprints` (model name -> PolicyFingerprint) whose recorded policy_fingerprint is the
/// same. A folder without an evaluation, or with files that cannot be read, offers nothing and
/// says why.
ReusableEpisodes FindReusableEpisodes(const std::filesystem::path& folder, const Config& config,
                                      const ConfigSchema& schema,
                                      const std::vector<std::string>& free_keys,
                                      const std::vector<EvaluationEpisode>& episodes,
                                      const std::map<std::string, std::string>& fingerprints);

}  // namespace colav

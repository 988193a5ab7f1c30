#include "eval/reused_episodes.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

#include "eval/episode_table.h"
#include "src/csv_table.h"
#include "src/run_folder.h"

namespace colav {
namespace {

// The test scenarios' (name, seed text) in episodes.csv's form.
std::vector<std::pair<std::string, std::string>> ScenarioKeys(
    const std::vector<EvaluationEpisode>& episodes) {
  std::vector<std::pair<std::string, std::string>> keys;
  keys.reserve(episodes.size());
  for (const EvaluationEpisode& episode : episodes) {
    keys.emplace_back(episode.name, episode.seed ? std::to_string(*episode.seed) : "");
  }
  return keys;
}

// Why the folder's evaluation was not run as `planned` is (scenarios aside); none when it was.
std::optional<std::string> Mismatch(const std::filesystem::path& folder,
                                    const PlannedEvaluation& planned,
                                    const nlohmann::json& summary) {
  if (summary.value("scenarios", "") != "test") return "it did not run the test scenarios";
  const std::string build_id = summary.value("evaluator_build_id", "");
  if (build_id != planned.build_id) {
    return "another build of evaluate ran it (build id '" + build_id + "', this one's '" +
           planned.build_id + "')";
  }
  const Config recorded = Config::Load(planned.schema, (folder / "config.yaml").string());
  if (const auto differing = FirstDifferingSetting(planned.config, recorded, planned.free_keys)) {
    return "it ran with " + differing->key + " = " + differing->recorded_value + ", not " +
           differing->value;
  }
  return std::nullopt;
}

// The episodes of the models in `wanted` (name -> fingerprint) that `summary` records with the
// same fingerprint, from `table` (episodes.csv), if their rows are exactly `scenarios`.
std::map<std::string, std::vector<EpisodeMetrics>> EpisodesOfUnchangedModels(
    const nlohmann::json& summary, const CsvTable& table,
    const std::vector<std::pair<std::string, std::string>>& scenarios,
    const std::map<std::string, std::string>& wanted) {
  std::map<std::string, std::vector<EpisodeMetrics>> by_model;
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> keys;
  for (const nlohmann::json& model : summary.at("models")) {
    const auto fingerprint = wanted.find(model.at("name").get<std::string>());
    if (fingerprint != wanted.end() &&
        model.value("policy_fingerprint", "") == fingerprint->second) {
      by_model[fingerprint->first];
    }
  }
  for (const std::vector<std::string>& row : table.rows) {
    const auto model = by_model.find(row.at(0));
    if (model == by_model.end()) continue;
    model->second.push_back(EpisodeMetricsOfRow(row));
    keys[row.at(0)].emplace_back(row.at(1), row.at(2));
  }
  for (auto model = by_model.begin(); model != by_model.end();) {
    model = keys[model->first] == scenarios ? std::next(model) : by_model.erase(model);
  }
  return by_model;
}

}  // namespace

ReusableEpisodes FindReusableEpisodes(const std::filesystem::path& folder,
                                      const PlannedEvaluation& planned,
                                      const std::map<std::string, std::string>& fingerprints) {
  ReusableEpisodes reusable;
  const std::filesystem::path summary_path = folder / "summary.json";
  if (!std::filesystem::is_regular_file(summary_path)) {
    reusable.why_none = folder.string() + " holds no evaluation";
    return reusable;
  }
  try {
    std::ifstream in(summary_path);
    const nlohmann::json summary = nlohmann::json::parse(in);
    if (const auto mismatch = Mismatch(folder, planned, summary)) {
      reusable.why_none = folder.string() + ": " + *mismatch;
      return reusable;
    }
    const CsvTable table = ReadCsvTable(folder / "episodes.csv");
    if (fmt::format("{}", fmt::join(table.header, ",")) != EpisodeTableHeader()) {
      reusable.why_none = (folder / "episodes.csv").string() + ": not " + EpisodeTableHeader();
      return reusable;
    }
    reusable.by_model =
        EpisodesOfUnchangedModels(summary, table, ScenarioKeys(planned.episodes), fingerprints);
  } catch (const std::exception& error) {  // a malformed or half-written earlier evaluation
    reusable.by_model.clear();
    reusable.why_none = error.what();
    return reusable;
  }
  if (reusable.by_model.empty()) {
    reusable.why_none = folder.string() + ": no model with the same name and policy file";
  }
  return reusable;
}

}  // namespace colav

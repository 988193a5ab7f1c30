// What a train_vae run reports: per seed (seed_<k>/result.json, seed_<k>/losses.csv) and across
// seeds (summary.json; summary.md in the form of the paper's VAE table: mean, Student-t 95 % CI
// and standard deviation of the test error).
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "train/vae/config.h"
#include "train/vae/trainer.h"

namespace colav {

struct SeedResult {
  std::int64_t index = 0;   ///< k of seed_<k>
  std::uint64_t seed = 0;   ///< the run's derived seed
  double test_error = 0.0;  ///< mean per-sample BCE + beta * KL, one sampled z
  double test_bce = 0.0;
  double test_kl = 0.0;
  std::int64_t active_dimensions = 0;
  std::vector<double> kl_per_dimension;
  double seconds = 0.0;  ///< training (validation included) and testing
  std::vector<EpochLosses> history;
};

nlohmann::json SeedResultToJson(const SeedResult& result);
/// A malformed result is a UserError naming `origin`.
SeedResult SeedResultFromJson(const nlohmann::json& json, const std::string& origin);

/// "epoch,train_bce,train_kl,val_bce,val_kl,seconds" and one row per epoch.
std::string LossesCsv(const std::vector<EpochLosses>& history);

/// summary.json and summary.md in `run_dir`.
void WriteRunSummary(const std::filesystem::path& run_dir, const VaeTrainingOptions& options,
                     const std::vector<SeedResult>& results);

/// "ShallowConvVAE (12)".
std::string PaperModelName(const VaeTrainingOptions& options);

}  // namespace colav

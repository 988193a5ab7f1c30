// One seed of a train_vae run, with its folder RUN_DIR/seed_<k>/: trains (resuming from
// checkpoint.pt when present), writes losses.csv after every epoch, then encoder.pt and vae.pt
// (TorchScript), tests, and writes result.json, which marks the seed as finished: a rerun of the
// same command skips it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "models/conv_vae.h"
#include "train/vae/config.h"
#include "train/vae/data.h"
#include "train/vae/summary.h"

namespace colav {

/// The seed of run k, derived from the master seed.
std::uint64_t VaeRunSeed(const VaeTrainingOptions& options, std::int64_t index);

/// The settings a checkpoint or result must share to be resumed or reused.
std::string VaeRunSignature(const VaeTrainingOptions& options, std::int64_t index);

/// SIGINT or SIGTERM stopped the run after an epoch, whose checkpoint the same command resumes
/// from (the message says where).
class TrainingStopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Trains, exports and tests seed `index` in `seed_dir` (or reuses its finished result). Throws a
/// TrainingStopped when a stop was requested (Ctrl-C) after saving the checkpoint.
SeedResult RunVaeSeed(const VaeData& data, const VaeTrainingOptions& options, std::int64_t index,
                      const std::filesystem::path& seed_dir);

/// The trained model of a finished seed folder, rebuilt from its checkpoint (for figures).
ConvVae LoadSeedModel(const VaeTrainingOptions& options, std::int64_t index,
                      const std::filesystem::path& seed_dir);

}  // namespace colav

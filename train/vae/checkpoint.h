// The resumable state of one training seed: model and optimizer state, the epochs done with their
// losses, and the time spent, in one file written atomically after every epoch. A signature of
// the settings guards against resuming under other settings.
#pragma once

#include <torch/torch.h>

#include <filesystem>
#include <string>
#include <vector>

#include "models/adam.h"
#include "models/conv_vae.h"
#include "train/vae/trainer.h"

namespace colav {

struct VaeProgress {
  std::vector<EpochLosses> history;  ///< one entry per finished epoch
  double seconds = 0.0;              ///< training and evaluation time so far
};

void SaveVaeCheckpoint(const std::filesystem::path& path, const std::string& signature,
                       ConvVae& model, Adam& optimizer, const VaeProgress& progress);

/// Restores model, optimizer and progress from `path`. A file made with another signature, or
/// one that cannot be read, is a UserError naming it.
VaeProgress LoadVaeCheckpoint(const std::filesystem::path& path, const std::string& signature,
                              ConvVae& model, Adam& optimizer);

}  // namespace colav

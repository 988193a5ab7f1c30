// The VAE dataset as tensors: the file's ranges turned into closeness (1 - d/150 by default, the
// paper's transform; the reference environment's log transform as an option), one tensor per
// split, and the paper's training noise, drawn per training seed.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <filesystem>

#include "env/environment_spec.h"

namespace colav {

struct VaeData {
  torch::Tensor train;       ///< float32 [n_train, 180] closeness, without noise
  torch::Tensor validation;  ///< float32 [n_validation, 180]
  torch::Tensor test;        ///< float32 [n_test, 180]
  torch::Tensor test_group;  ///< int64 [n_test], ScanGroup of each test row
};

/// Reads a generate_dataset file (errors as ReadScanDataset) and transforms its ranges. A split
/// without rows is a UserError naming the file.
VaeData LoadVaeData(const std::filesystem::path& path, ClosenessTransform transform);

/// x + N(0, variance) noise, drawn from a generator seeded with `seed` (the paper's sigma^2 =
/// 0.007 on the training split: sd 0.084, about 12.5 m). The reference does not clip, and BCE
/// accepts the targets outside [0, 1] that result; but BCE is then unbounded below (a target t < 0
/// rewards p -> 0 with |t| * 100 per ray at PyTorch's log clamp), which a deep enough VAE learns to
/// exploit from its own noisy input. `clip` keeps the noisy values in [0, 1].
torch::Tensor WithTrainingNoise(const torch::Tensor& x, double variance, std::uint64_t seed,
                                bool clip = false);

}  // namespace colav

// Figures of the VAE part of the paper, drawn with gnuplot: reconstructions of test scans in
// polar form like the simulator's view (input blue, reconstruction red, as the paper), the
// zero-padding versus CPTC-1D comparison, and training curves.
//
// Polar panels put ray i at its simulator bearing, -pi + (i + 1) * 2 deg from the heading, with
// the heading up; the dashed line marks the seam between ray 179 and ray 0 (behind the vessel),
// where a zero-padded decoder sees the two ends of the scan as unrelated.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "env/environment_spec.h"
#include "models/conv_vae.h"
#include "train/vae/trainer.h"

namespace colav {

/// Range (m) of a closeness value: the inverse of Closeness(range, transform).
torch::Tensor RangesFromCloseness(const torch::Tensor& closeness, ClosenessTransform transform);

/// The model's mean reconstruction decode(mu(x)) of scans x [k, 180], without autograd.
torch::Tensor MeanReconstruction(ConvVae& model, const torch::Tensor& x);

/// `count` distinct rows of `scans` [n, 180] that see at least one obstacle, in a seeded random
/// order; with `near_seam`, only rows with an obstacle within `seam_rays` rays of the seam.
std::vector<std::int64_t> PickScans(const torch::Tensor& scans, std::int64_t count,
                                    std::uint64_t seed, bool near_seam, std::int64_t seam_rays = 6);

/// Grid of polar panels: for each scan, the input and its reconstruction by each model (one row of
/// panels per model, labelled by `model_names`).
void DrawPolarReconstructions(const torch::Tensor& scans, const std::vector<ConvVae>& models,
                              const std::vector<std::string>& model_names,
                              ClosenessTransform transform, const std::string& title,
                              const std::filesystem::path& png);

/// Per-sample train (noisy data) and validation loss, bce + beta * kl, per epoch; one pair of
/// curves per seed.
void DrawTrainingCurves(const std::vector<std::vector<EpochLosses>>& histories, double beta,
                        const std::string& title, const std::filesystem::path& png);

}  // namespace colav

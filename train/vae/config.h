// train_vae's options and the configuration keys bound to them (configs/vae.yaml lists the
// defaults).
#pragma once

#include <cstdint>
#include <string>

#include "env/environment_spec.h"
#include "models/conv_vae.h"
#include "src/options_binding.h"

namespace colav {

struct VaeTrainingOptions {
  std::string data_path;
  ClosenessTransform transform = ClosenessTransform::kLinear;
  double train_noise_variance = 0.007;
  bool clip_noisy_scans = false;  ///< see WithTrainingNoise; false = the reference
  VaeOptions model;
  double beta = 1.0;
  std::int64_t epochs = 25;
  std::int64_t batch_size = 64;
  double learning_rate = 1e-3;
  std::int64_t seeds = 1;
  std::uint64_t seed = 0;  ///< master seed; seed k of the run derives from it
  int threads = 1;         ///< LibTorch intra-op threads
  std::int64_t evaluation_batch_size = 2048;
  bool figures = true;
};

/// The data.*, vae.*, training.*, evaluation.* and figures.* keys; reading without a data path
/// is a UserError.
OptionsBinding<VaeTrainingOptions> VaeTrainingBinding();

/// "shallow, latent 12, beta 1, circular decoder", for logs and tables.
std::string DescribeVae(const VaeTrainingOptions& options);

}  // namespace colav

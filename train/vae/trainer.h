// One VAE training run (one seed) in memory: Adam (models/adam.h) on the batch-averaged loss BCE +
// beta
// * KL (models/vae_loss.h), the whole training split in one tensor, shuffled once per epoch by a
// seeded permutation and cut into contiguous minibatches (no per-sample copies), then a
// validation pass without autograd.
//
// Every random thing is seeded from the run's seed: the initial weights ("vae.init"), the
// training noise ("vae.noise"), each epoch's shuffle ("vae.shuffle", epoch) and its z samples
// ("vae.sample", epoch), so a run resumed after epoch e continues exactly as if uninterrupted.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <functional>
#include <vector>

#include "models/adam.h"
#include "models/conv_vae.h"
#include "train/vae/config.h"
#include "train/vae/data.h"

namespace colav {

struct EpochLosses {
  std::int64_t epoch = 0;  ///< 1-based
  double train_bce = 0.0;  ///< per-sample means over the epoch (noisy training data)
  double train_kl = 0.0;
  double validation_bce = 0.0;
  double validation_kl = 0.0;
  double seconds = 0.0;  ///< wall time of the epoch, validation included
};

/// PyTorch's default Adam (betas 0.9, 0.999, eps 1e-8) with the VAE trainer's rounding.
Adam MakeVaeOptimizer(std::vector<torch::Tensor> parameters, double learning_rate);

/// A VAE with weights drawn from the stream (seed, "vae.init").
ConvVae MakeVae(const VaeOptions& options, std::uint64_t seed);

class VaeTrainer {
 public:
  /// Draws the training noise and the initial weights of run `seed`. `data` must outlive it.
  VaeTrainer(const VaeTrainingOptions& options, const VaeData& data, std::uint64_t seed);

  /// Trains epoch `epoch` (1-based) and validates. on_batch(scans done in this epoch, mean loss so
  /// far) is called after every minibatch. A NaN or infinite loss or parameter throws
  /// TrainingDiverged (src/training_diverged.h) before the epoch's results can be saved.
  EpochLosses RunEpoch(std::int64_t epoch,
                       const std::function<void(std::int64_t, double)>& on_batch = {});

  ConvVae& model() { return model_; }
  Adam& optimizer() { return optimizer_; }
  std::uint64_t seed() const { return seed_; }

 private:
  VaeTrainingOptions options_;
  const VaeData& data_;
  std::uint64_t seed_;
  torch::Tensor noisy_train_;
  torch::Tensor shuffled_train_;  // reused every epoch
  ConvVae model_;
  Adam optimizer_;
};

/// Trains `options.epochs` epochs of run `seed` and returns the model (figures, tests).
ConvVae TrainVaeInMemory(const VaeTrainingOptions& options, const VaeData& data,
                         std::uint64_t seed);

}  // namespace colav

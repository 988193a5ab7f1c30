#include "train/vae/trainer.h"

#include <ATen/CPUGeneratorImpl.h>

#include <chrono>
#include <cmath>
#include <string>
#include <utility>

#include "models/circular_conv.h"
#include "models/vae_loss.h"
#include "src/seeding.h"
#include "src/training_diverged.h"
#include "train/vae/evaluation.h"

namespace colav {
namespace {

torch::Generator SeededGenerator(std::uint64_t seed, const char* stream, std::uint64_t index) {
  return at::make_generator<at::CPUGeneratorImpl>(DeriveSeed(seed, stream, index));
}

// TrainingDiverged when a loss of `epoch`, or a parameter after it, is NaN or infinite.
void RequireFinite(double value, const char* what, std::int64_t epoch) {
  if (!std::isfinite(value)) {
    throw TrainingDiverged(std::string(what) + " is " + std::to_string(value) + " in epoch " +
                           std::to_string(epoch) + " (learning rate too high, or bad data?)");
  }
}

void RequireFiniteParameters(ConvVae& model, std::int64_t epoch) {
  for (const auto& parameter : model->named_parameters()) {
    if (!torch::isfinite(parameter.value()).all().item<bool>()) {
      throw TrainingDiverged("parameter " + parameter.key() + " is not finite after epoch " +
                             std::to_string(epoch) + " (learning rate too high?)");
    }
  }
}

}  // namespace

Adam MakeVaeOptimizer(std::vector<torch::Tensor> parameters, double learning_rate) {
  AdamOptions options;
  options.learning_rate = learning_rate;
  options.eps = 1e-8;
  return Adam(std::move(parameters), options, AdamArithmetic::kDoubleStep);
}

ConvVae MakeVae(const VaeOptions& options, std::uint64_t seed) {
  ConvVae vae(options);
  torch::Generator generator = SeededGenerator(seed, "vae.init", 0);
  RedrawLayerParameters(*vae, generator);
  return vae;
}

VaeTrainer::VaeTrainer(const VaeTrainingOptions& options, const VaeData& data, std::uint64_t seed)
    : options_(options),
      data_(data),
      seed_(seed),
      noisy_train_(WithTrainingNoise(data.train, options.train_noise_variance,
                                     DeriveSeed(seed, "vae.noise"), options.clip_noisy_scans)),
      shuffled_train_(torch::empty_like(noisy_train_)),
      model_(MakeVae(options.model, seed)),
      optimizer_(MakeVaeOptimizer(model_->parameters(), options.learning_rate)) {}

EpochLosses VaeTrainer::RunEpoch(std::int64_t epoch,
                                 const std::function<void(std::int64_t, double)>& on_batch) {
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t count = noisy_train_.size(0);
  torch::Generator shuffle =
      SeededGenerator(seed_, "vae.shuffle", static_cast<std::uint64_t>(epoch));
  torch::Generator sample = SeededGenerator(seed_, "vae.sample", static_cast<std::uint64_t>(epoch));
  // One gather per epoch; the minibatches are then contiguous views.
  torch::index_select_out(shuffled_train_, noisy_train_, 0,
                          torch::randperm(count, shuffle, torch::kLong));

  double bce_sum = 0.0;
  double kl_sum = 0.0;
  for (std::int64_t begin = 0; begin < count; begin += options_.batch_size) {
    const std::int64_t size = std::min(options_.batch_size, count - begin);
    const torch::Tensor x = shuffled_train_.narrow(0, begin, size);
    optimizer_.ZeroGrad();
    const VaeLoss loss = ComputeVaeLoss(model_->forward(x, sample), x, options_.beta);
    loss.total.backward();
    optimizer_.Step();
    // Read the scalars directly: item() would dispatch an operator per call.
    const auto bce = static_cast<double>(*loss.bce.data_ptr<float>());
    const auto kl = static_cast<double>(*loss.kl.data_ptr<float>());
    // Checked after the step, so the step's NaN never reaches a checkpoint: the epoch is lost.
    RequireFinite(bce, "the training BCE", epoch);
    RequireFinite(kl, "the training KL", epoch);
    bce_sum += bce * static_cast<double>(size);
    kl_sum += kl * static_cast<double>(size);
    if (on_batch) {
      on_batch(begin + size,
               (bce_sum + options_.beta * kl_sum) / static_cast<double>(begin + size));
    }
  }

  RequireFiniteParameters(model_, epoch);
  const VaeEvaluation validation =
      EvaluateVae(model_, data_.validation, options_.beta,
                  DeriveSeed(seed_, "vae.validation", static_cast<std::uint64_t>(epoch)),
                  options_.evaluation_batch_size);
  RequireFinite(validation.bce, "the validation BCE", epoch);
  RequireFinite(validation.kl, "the validation KL", epoch);
  EpochLosses losses;
  losses.epoch = epoch;
  losses.train_bce = bce_sum / static_cast<double>(count);
  losses.train_kl = kl_sum / static_cast<double>(count);
  losses.validation_bce = validation.bce;
  losses.validation_kl = validation.kl;
  losses.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return losses;
}

ConvVae TrainVaeInMemory(const VaeTrainingOptions& options, const VaeData& data,
                         std::uint64_t seed) {
  VaeTrainer trainer(options, data, seed);
  for (std::int64_t epoch = 1; epoch <= options.epochs; ++epoch) trainer.RunEpoch(epoch);
  return trainer.model();
}

}  // namespace colav

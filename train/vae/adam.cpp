#include "train/vae/adam.h"

#include <cmath>
#include <string>
#include <utility>

namespace colav {
namespace {

constexpr double kBeta1 = 0.9;
constexpr double kBeta2 = 0.999;
constexpr double kEpsilon = 1e-8;

}  // namespace

LoopAdam::LoopAdam(std::vector<torch::Tensor> parameters, double learning_rate)
    : parameters_(std::move(parameters)), learning_rate_(learning_rate) {
  for (const torch::Tensor& parameter : parameters_) {
    TORCH_CHECK(parameter.is_contiguous() && parameter.scalar_type() == torch::kFloat32 &&
                    parameter.device().is_cpu(),
                "LoopAdam needs contiguous float32 CPU parameters");
    first_moments_.push_back(torch::zeros_like(parameter));
    second_moments_.push_back(torch::zeros_like(parameter));
  }
}

void LoopAdam::ZeroGrad() {
  for (torch::Tensor& parameter : parameters_) parameter.mutable_grad().reset();
}

void LoopAdam::Step() {
  ++steps_;
  const double step_size = learning_rate_ / (1.0 - std::pow(kBeta1, steps_));
  const double bias_correction2_sqrt = std::sqrt(1.0 - std::pow(kBeta2, steps_));
  const auto beta1 = static_cast<float>(kBeta1);
  const auto beta2 = static_cast<float>(kBeta2);
  for (std::size_t k = 0; k < parameters_.size(); ++k) {
    torch::Tensor& parameter = parameters_[k];
    if (!parameter.grad().defined()) continue;
    const torch::Tensor gradient = parameter.grad().contiguous();
    const float* g = gradient.data_ptr<float>();
    float* p = parameter.data_ptr<float>();
    float* m = first_moments_[k].data_ptr<float>();
    float* v = second_moments_[k].data_ptr<float>();
    for (std::int64_t i = 0; i < parameter.numel(); ++i) {
      m[i] = beta1 * m[i] + (1.0F - beta1) * g[i];
      v[i] = beta2 * v[i] + (1.0F - beta2) * g[i] * g[i];
      const double denominator =
          std::sqrt(static_cast<double>(v[i])) / bias_correction2_sqrt + kEpsilon;
      p[i] -= static_cast<float>(step_size * m[i] / denominator);
    }
  }
}

void LoopAdam::Save(torch::serialize::OutputArchive& archive) const {
  archive.write("steps", torch::tensor(steps_, torch::kInt64));
  for (std::size_t k = 0; k < parameters_.size(); ++k) {
    archive.write("m" + std::to_string(k), first_moments_[k]);
    archive.write("v" + std::to_string(k), second_moments_[k]);
  }
}

void LoopAdam::Load(torch::serialize::InputArchive& archive) {
  torch::Tensor steps;
  archive.read("steps", steps);
  for (std::size_t k = 0; k < parameters_.size(); ++k) {
    torch::Tensor m;
    torch::Tensor v;
    archive.read("m" + std::to_string(k), m);
    archive.read("v" + std::to_string(k), v);
    TORCH_CHECK(m.sizes() == parameters_[k].sizes() && v.sizes() == parameters_[k].sizes(),
                "LoopAdam state does not fit parameter ", k);
    first_moments_[k].copy_(m);
    second_moments_[k].copy_(v);
  }
  steps_ = steps.item<std::int64_t>();
}

}  // namespace colav

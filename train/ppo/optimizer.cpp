#include "train/ppo/optimizer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "models/actor_critic_kernels.h"

namespace colav {
namespace {

// clip_grad_norm_'s guard against a zero norm.
constexpr double kNormEpsilon = 1e-6;

float* Data(const torch::Tensor& tensor) { return tensor.data_ptr<float>(); }
int Size(const torch::Tensor& tensor) { return static_cast<int>(tensor.numel()); }

}  // namespace

PolicyOptimizer::PolicyOptimizer(std::vector<torch::Tensor> parameters, AdamOptions options)
    : parameters_(std::move(parameters)), options_(options) {
  for (const torch::Tensor& parameter : parameters_) {
    TORCH_CHECK(parameter.is_contiguous() && parameter.scalar_type() == torch::kFloat32,
                "PolicyOptimizer needs contiguous float32 parameters");
    exp_avg_.push_back(torch::zeros_like(parameter));
    exp_avg_sq_.push_back(torch::zeros_like(parameter));
  }
}

double PolicyOptimizer::GradientNorm(const std::vector<torch::Tensor>& gradients) {
  double sum = 0.0;
  for (const torch::Tensor& gradient : gradients) {
    sum += kernels::SumOfSquares(Data(gradient), Size(gradient));
  }
  return std::sqrt(sum);
}

double PolicyOptimizer::ClipCoefficient(double norm, double max_norm) {
  return std::min(1.0, max_norm / (norm + kNormEpsilon));
}

void PolicyOptimizer::Step(const std::vector<torch::Tensor>& gradients, double gradient_scale) {
  TORCH_CHECK(gradients.size() == parameters_.size(), "one gradient per parameter expected");
  ++step_count_;
  const double t = static_cast<double>(step_count_);
  const kernels::AdamCoefficients coefficients{
      static_cast<float>(options_.beta1),
      static_cast<float>(options_.beta2),
      static_cast<float>(options_.eps),
      static_cast<float>(options_.learning_rate / (1.0 - std::pow(options_.beta1, t))),
      static_cast<float>(std::sqrt(1.0 - std::pow(options_.beta2, t))),
      static_cast<float>(gradient_scale)};
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    kernels::AdamUpdate(coefficients, Data(gradients[i]), Data(exp_avg_[i]), Data(exp_avg_sq_[i]),
                        Data(parameters_[i]), Size(parameters_[i]));
  }
}

void PolicyOptimizer::Save(torch::serialize::OutputArchive& archive) const {
  archive.write("step_count", torch::tensor(step_count_));
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    archive.write("exp_avg/" + std::to_string(i), exp_avg_[i]);
    archive.write("exp_avg_sq/" + std::to_string(i), exp_avg_sq_[i]);
  }
}

void PolicyOptimizer::Load(torch::serialize::InputArchive& archive) {
  torch::Tensor step_count;
  archive.read("step_count", step_count);
  step_count_ = step_count.item<std::int64_t>();
  torch::NoGradGuard no_grad;
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    for (auto [name, state] :
         {std::pair{"exp_avg/", exp_avg_[i]}, {"exp_avg_sq/", exp_avg_sq_[i]}}) {
      torch::Tensor stored;
      archive.read(name + std::to_string(i), stored);
      TORCH_CHECK(stored.sizes() == state.sizes(), "optimiser state of the wrong shape");
      state.copy_(stored);  // in place: the tensors' storage stays where the kernels expect it
    }
  }
}

}  // namespace colav

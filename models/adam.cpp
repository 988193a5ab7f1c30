#include "models/adam.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "models/actor_critic_kernels.h"
#include "models/float_data.h"

namespace colav {
namespace {

// clip_grad_norm_'s guard against a zero norm.
constexpr double kNormEpsilon = 1e-6;

int Size(const torch::Tensor& tensor) { return static_cast<int>(tensor.numel()); }

// AdamArithmetic::kDoubleStep on n values.
void AdamUpdateWithDoubleStep(const AdamOptions& options, double step_size,
                              double sqrt_bias_correction2, float gradient_scale, const float* grad,
                              float* exp_avg, float* exp_avg_sq, float* param, int n) {
  const auto beta1 = static_cast<float>(options.beta1);
  const auto beta2 = static_cast<float>(options.beta2);
  for (int i = 0; i < n; ++i) {
    const float g = grad[i] * gradient_scale;
    exp_avg[i] = beta1 * exp_avg[i] + (1.0F - beta1) * g;
    exp_avg_sq[i] = beta2 * exp_avg_sq[i] + (1.0F - beta2) * g * g;
    const double denominator =
        std::sqrt(static_cast<double>(exp_avg_sq[i])) / sqrt_bias_correction2 + options.eps;
    param[i] -= static_cast<float>(step_size * exp_avg[i] / denominator);
  }
}

}  // namespace

double GradientNorm(const std::vector<torch::Tensor>& gradients) {
  double sum = 0.0;
  for (const torch::Tensor& gradient : gradients) {
    sum += kernels::SumOfSquares(FloatData(gradient), Size(gradient));
  }
  return std::sqrt(sum);
}

double ClipCoefficient(double norm, double max_norm) {
  return std::min(1.0, max_norm / (norm + kNormEpsilon));
}

Adam::Adam(std::vector<torch::Tensor> parameters, AdamOptions options, AdamArithmetic arithmetic)
    : parameters_(std::move(parameters)), options_(options), arithmetic_(arithmetic) {
  for (const torch::Tensor& parameter : parameters_) {
    TORCH_CHECK(parameter.is_contiguous() && parameter.scalar_type() == torch::kFloat32 &&
                    parameter.device().is_cpu(),
                "Adam needs contiguous float32 CPU parameters");
    exp_avg_.push_back(torch::zeros_like(parameter));
    exp_avg_sq_.push_back(torch::zeros_like(parameter));
  }
}

void Adam::Step(const std::vector<torch::Tensor>& gradients, double gradient_scale) {
  TORCH_CHECK(gradients.size() == parameters_.size(), "one gradient per parameter expected");
  ++step_count_;
  const double t = static_cast<double>(step_count_);
  const double step_size = options_.learning_rate / (1.0 - std::pow(options_.beta1, t));
  const double sqrt_bias_correction2 = std::sqrt(1.0 - std::pow(options_.beta2, t));
  const kernels::AdamCoefficients coefficients{
      static_cast<float>(options_.beta1),        static_cast<float>(options_.beta2),
      static_cast<float>(options_.eps),          static_cast<float>(step_size),
      static_cast<float>(sqrt_bias_correction2), static_cast<float>(gradient_scale)};
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    const torch::Tensor& gradient = gradients[i];
    if (!gradient.defined()) continue;
    TORCH_CHECK(gradient.is_contiguous() && gradient.numel() == parameters_[i].numel(),
                "Adam needs contiguous gradients of the parameters' sizes");
    if (arithmetic_ == AdamArithmetic::kFloat) {
      kernels::AdamUpdate(coefficients, FloatData(gradient), FloatData(exp_avg_[i]),
                          FloatData(exp_avg_sq_[i]), FloatData(parameters_[i]),
                          Size(parameters_[i]));
    } else {
      AdamUpdateWithDoubleStep(options_, step_size, sqrt_bias_correction2,
                               coefficients.gradient_scale, FloatData(gradient),
                               FloatData(exp_avg_[i]), FloatData(exp_avg_sq_[i]),
                               FloatData(parameters_[i]), Size(parameters_[i]));
    }
  }
}

void Adam::Step() {
  std::vector<torch::Tensor> gradients;
  gradients.reserve(parameters_.size());
  for (const torch::Tensor& parameter : parameters_) {
    const torch::Tensor& gradient = parameter.grad();
    gradients.push_back(gradient.defined() ? gradient.contiguous() : gradient);
  }
  Step(gradients);
}

void Adam::ZeroGrad() {
  for (torch::Tensor& parameter : parameters_) parameter.mutable_grad().reset();
}

void Adam::Save(torch::serialize::OutputArchive& archive) const {
  archive.write("step_count", torch::tensor(step_count_));
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    archive.write("exp_avg/" + std::to_string(i), exp_avg_[i]);
    archive.write("exp_avg_sq/" + std::to_string(i), exp_avg_sq_[i]);
  }
}

void Adam::Load(torch::serialize::InputArchive& archive) {
  torch::Tensor step_count;
  archive.read("step_count", step_count);
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
  step_count_ = step_count.item<std::int64_t>();
}

}  // namespace colav

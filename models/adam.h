// Adam (torch.optim.Adam without weight decay or amsgrad) and global gradient-norm clipping
// (torch::nn::utils::clip_grad_norm_), run as plain loops over each parameter's memory. The
// trainers' parameter tensors are few and small, so LibTorch's ~10 operators per tensor and step
// cost more in dispatch and allocation than the arithmetic itself. The update:
//   m = b1 m + (1 - b1) g;  v = b2 v + (1 - b2) g^2
//   p -= lr / (1 - b1^t) * m / (sqrt(v) / sqrt(1 - b2^t) + eps)
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <vector>

namespace colav {

struct AdamOptions {
  double learning_rate = 2e-4;
  double beta1 = 0.9;
  double beta2 = 0.999;
  double eps = 1e-5;  ///< SB3's PPO default (PyTorch's is 1e-8)
};

/// How a step rounds. The PPO and VAE trainers were written with different arithmetic and their
/// trained results are pinned bit for bit, so both roundings are kept.
enum class AdamArithmetic {
  kFloat,       ///< everything in float, 4 values at a time (the PPO learner)
  kDoubleStep,  ///< moments in float (v += ((1 - b2) g) g), the parameter step in double (VAE)
};

/// The global L2 norm of `gradients`.
double GradientNorm(const std::vector<torch::Tensor>& gradients);
/// The factor clip_grad_norm_ scales gradients of global norm `norm` by: min(1, max_norm /
/// (norm + 1e-6)).
double ClipCoefficient(double norm, double max_norm);

class Adam {
 public:
  /// `parameters` (contiguous float32 CPU tensors) are updated in place.
  Adam(std::vector<torch::Tensor> parameters, AdamOptions options,
       AdamArithmetic arithmetic = AdamArithmetic::kFloat);

  /// One step with gradient_scale * `gradients` (contiguous, aligned with the parameters, not
  /// modified); a parameter whose gradient is undefined is left as it is.
  void Step(const std::vector<torch::Tensor>& gradients, double gradient_scale = 1.0);
  /// One step with the parameters' own (autograd) gradients.
  void Step();
  /// Drops the parameters' autograd gradients, so the next backward hands over fresh gradient
  /// tensors without an accumulation pass.
  void ZeroGrad();

  /// The rate of the following steps (a schedule's); the moments are kept.
  void set_learning_rate(double learning_rate) { options_.learning_rate = learning_rate; }
  std::int64_t step_count() const { return step_count_; }
  const std::vector<torch::Tensor>& exp_avg() const { return exp_avg_; }
  const std::vector<torch::Tensor>& exp_avg_sq() const { return exp_avg_sq_; }

  void Save(torch::serialize::OutputArchive& archive) const;
  /// Restores a state written by Save for the same parameter shapes (c10::Error if not).
  void Load(torch::serialize::InputArchive& archive);

 private:
  std::vector<torch::Tensor> parameters_;
  AdamOptions options_;
  AdamArithmetic arithmetic_;
  std::vector<torch::Tensor> exp_avg_, exp_avg_sq_;
  std::int64_t step_count_ = 0;
};

}  // namespace colav

// Adam and global gradient-norm clipping over the policy's trainable parameters, with the
// semantics of torch::optim::Adam (no weight decay, no amsgrad) and
// torch::nn::utils::clip_grad_norm_, run as single vectorised loops over the raw tensors
// (LibTorch's versions launch ~10 operators per parameter tensor per step).
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

class PolicyOptimizer {
 public:
  /// `parameters` (contiguous float32 CPU tensors) are updated in place.
  PolicyOptimizer(std::vector<torch::Tensor> parameters, AdamOptions options);

  /// The global L2 norm of `gradients`.
  static double GradientNorm(const std::vector<torch::Tensor>& gradients);
  /// The factor clip_grad_norm_ scales gradients of global norm `norm` by: min(1, max_norm /
  /// (norm + 1e-6)).
  static double ClipCoefficient(double norm, double max_norm);
  /// One Adam step with gradient_scale * `gradients` (aligned with the parameters, not modified).
  void Step(const std::vector<torch::Tensor>& gradients, double gradient_scale = 1.0);

  std::int64_t step_count() const { return step_count_; }
  const std::vector<torch::Tensor>& exp_avg() const { return exp_avg_; }
  const std::vector<torch::Tensor>& exp_avg_sq() const { return exp_avg_sq_; }

  void Save(torch::serialize::OutputArchive& archive) const;
  /// Restores a state written by Save for the same parameter shapes (std::runtime_error if not).
  void Load(torch::serialize::InputArchive& archive);

 private:
  std::vector<torch::Tensor> parameters_;
  AdamOptions options_;
  std::vector<torch::Tensor> exp_avg_, exp_avg_sq_;
  std::int64_t step_count_ = 0;
};

}  // namespace colav

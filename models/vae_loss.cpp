#include "models/vae_loss.h"

namespace colav {
namespace {

// PyTorch's binary_cross_entropy clamps each log term at -100, so a saturated reconstruction
// (exactly 0 or 1 in float) costs at most 100 nats instead of infinity, and bounds the
// denominator of the gradient by this epsilon.
constexpr double kLogClamp = -100.0;
constexpr double kGradientEpsilon = 1e-12;

// -sum_n [t log r + (1 - t) log(1 - r)] over each row of r, t [B, N] -> [B], as PyTorch's
// binary_cross_entropy (reduction none, then summed) computes it, but from vectorised tensor ops
// and with its gradient in one node: that kernel evaluates its logarithms one element at a time,
// which made it the most expensive part of a training step. No gradient flows to the target.
class BinaryCrossEntropySum : public torch::autograd::Function<BinaryCrossEntropySum> {
 public:
  static torch::Tensor forward(torch::autograd::AutogradContext* context,
                               const torch::Tensor& reconstruction, const torch::Tensor& target) {
    TORCH_CHECK(reconstruction.sizes() == target.sizes() && reconstruction.dim() == 2,
                "reconstruction ", reconstruction.sizes(), " and target ", target.sizes(),
                " must both be [B, N]");
    context->save_for_backward({reconstruction, target});
    const torch::Tensor log_r = torch::log(reconstruction).clamp_min_(kLogClamp);
    const torch::Tensor log_one_minus_r = torch::log1p(-reconstruction).clamp_min_(kLogClamp);
    // t log r + (1 - t) log(1 - r) = lerp(log(1 - r), log r, t)
    return torch::lerp(log_one_minus_r, log_r, target).sum(1).neg_();
  }

  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* context,
                                                 torch::autograd::variable_list output_gradients) {
    const auto saved = context->get_saved_variables();
    const torch::Tensor& r = saved[0];
    const torch::Tensor& target = saved[1];
    const torch::Tensor denominator = (r * (1 - r)).clamp_min_(kGradientEpsilon);
    return {(r - target).div_(denominator).mul_(output_gradients[0].unsqueeze(1)), torch::Tensor()};
  }
};

// KL(N(mu, exp(logvar)) || N(0, 1)) = (mu^2 + exp(logvar) - 1 - logvar) / 2 per entry, with its
// gradient (mu, (exp(logvar) - 1) / 2) in one node.
class GaussianKlDivergence : public torch::autograd::Function<GaussianKlDivergence> {
 public:
  static torch::Tensor forward(torch::autograd::AutogradContext* context, const torch::Tensor& mu,
                               const torch::Tensor& logvar) {
    const torch::Tensor variance = logvar.exp();
    context->save_for_backward({mu, variance});
    return mu.square().add_(variance).sub_(logvar).sub_(1).mul_(0.5);
  }

  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* context,
                                                 torch::autograd::variable_list output_gradients) {
    const auto saved = context->get_saved_variables();
    const torch::Tensor& gradient = output_gradients[0];
    return {gradient * saved[0], (saved[1] - 1).mul_(0.5).mul_(gradient)};
  }
};

}  // namespace

VaeLoss ComputeVaeLoss(const ConvVaeImpl::Output& output, const torch::Tensor& target,
                       double beta) {
  const VaeLoss per_sample = ComputePerSampleVaeLoss(output, target, beta);
  const torch::Tensor bce = per_sample.bce.mean();
  const torch::Tensor kl = per_sample.kl.mean();
  return {torch::add(bce, kl, beta), bce, kl};
}

VaeLoss ComputePerSampleVaeLoss(const ConvVaeImpl::Output& output, const torch::Tensor& target,
                                double beta) {
  const torch::Tensor bce = BinaryCrossEntropySum::apply(output.reconstruction, target);
  const torch::Tensor kl = KlDivergence(output.mu, output.logvar).sum(1);
  return {torch::add(bce, kl, beta), bce, kl};
}

torch::Tensor KlDivergence(const torch::Tensor& mu, const torch::Tensor& logvar) {
  return GaussianKlDivergence::apply(mu, logvar);
}

torch::Tensor KlPerLatentDimension(const torch::Tensor& mu, const torch::Tensor& logvar) {
  return KlDivergence(mu, logvar).mean(0);
}

std::int64_t CountActiveLatentDimensions(const torch::Tensor& kl_per_dimension, double threshold) {
  return kl_per_dimension.gt(threshold).sum().item<std::int64_t>();
}

}  // namespace colav

#include "models/diagonal_gaussian.h"

#include <cmath>

namespace colav {
namespace {

// log(sqrt(2 pi)), the normalising constant of a unit Gaussian's log-density.
const double kLogSqrtTwoPi = 0.5 * std::log(2.0 * M_PI);

}  // namespace

torch::Tensor DiagonalGaussian::LogProb(const torch::Tensor& actions) const {
  const torch::Tensor z = (actions - mean) * torch::exp(-log_std);
  return (-0.5 * z.square() - log_std - kLogSqrtTwoPi).sum(-1);
}

torch::Tensor DiagonalGaussian::Entropy() const {
  return (0.5 + kLogSqrtTwoPi + log_std).sum(-1).expand({mean.size(0)});
}

torch::Tensor DiagonalGaussian::Sample(torch::Generator& generator) const {
  return mean + torch::exp(log_std) * torch::randn(mean.sizes(), generator, mean.options());
}

}  // namespace colav

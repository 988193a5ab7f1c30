#include "train/vae/evaluation.h"

#include <ATen/CPUGeneratorImpl.h>

#include "models/vae_loss.h"

namespace colav {

VaeEvaluation EvaluateVae(ConvVae& model, const torch::Tensor& x, double beta, std::uint64_t seed,
                          std::int64_t batch_size) {
  const torch::NoGradGuard no_grad;
  torch::Generator generator = at::make_generator<at::CPUGeneratorImpl>(seed);
  const std::int64_t count = x.size(0);
  double bce_sum = 0.0;
  double kl_sum = 0.0;
  torch::Tensor kl_per_dimension_sum = torch::zeros({model->options().latent_dims}, torch::kDouble);
  for (std::int64_t start = 0; start < count; start += batch_size) {
    const torch::Tensor batch = x.narrow(0, start, std::min(batch_size, count - start));
    const ConvVaeImpl::Output output = model->forward(batch, generator);
    const VaeLoss loss = ComputePerSampleVaeLoss(output, batch, beta);
    bce_sum += loss.bce.sum().item<double>();
    kl_sum += loss.kl.sum().item<double>();
    kl_per_dimension_sum += KlDivergence(output.mu, output.logvar).sum(0).to(torch::kDouble);
  }
  VaeEvaluation evaluation;
  const auto n = static_cast<double>(count);
  evaluation.bce = bce_sum / n;
  evaluation.kl = kl_sum / n;
  evaluation.total = evaluation.bce + beta * evaluation.kl;
  evaluation.kl_per_dimension = kl_per_dimension_sum / n;
  evaluation.active_dimensions = CountActiveLatentDimensions(evaluation.kl_per_dimension);
  return evaluation;
}

}  // namespace colav

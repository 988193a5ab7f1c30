#include "models/conv_vae.h"

#include <utility>

namespace colav {

ConvVaeImpl::ConvVaeImpl(VaeOptions options) : options_(options) {
  encoder_ = register_module(
      "encoder", VaeEncoder(VaeEncoderOptions{options_.architecture, options_.latent_dims}));
  decoder_ = register_module(
      "decoder", VaeDecoder(VaeDecoderOptions{options_.architecture, options_.latent_dims,
                                              options_.decoder_padding}));
}

ConvVaeImpl::Output ConvVaeImpl::forward(const torch::Tensor& x, torch::Generator generator) {
  auto [mu, logvar] = encoder_->forward(x);
  const torch::Tensor eps = torch::randn(mu.sizes(), std::move(generator), mu.options());
  const torch::Tensor z = mu + eps * torch::exp(0.5 * logvar);
  return {decoder_->forward(z), std::move(mu), std::move(logvar)};
}

}  // namespace colav

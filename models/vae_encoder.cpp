#include "models/vae_encoder.h"

namespace colav {

VaeEncoderImpl::VaeEncoderImpl(VaeEncoderOptions options) : options_(options) {
  TORCH_CHECK(options_.latent_dims > 0, "latent_dims must be positive, got ", options_.latent_dims);
  convs_ = register_module("convs", torch::nn::ModuleList());
  for (const ConvLayerSpec& layer : EncoderConvLayers(options_.architecture)) {
    convs_->push_back(CircularConv1d(
        CircularConv1dOptions(layer.in_channels, layer.out_channels, layer.kernel_size)
            .stride(layer.stride)
            .padding(layer.padding)));
  }
  fc_mu_ = register_module("fc_mu", torch::nn::Linear(kConvFeatureLength, options_.latent_dims));
  fc_logvar_ =
      register_module("fc_logvar", torch::nn::Linear(kConvFeatureLength, options_.latent_dims));
}

torch::Tensor VaeEncoderImpl::Features(const torch::Tensor& x) {
  TORCH_CHECK(x.dim() == 2 && x.size(1) == kScanLength, "encoder expects x of shape [B, ",
              kScanLength, "], got ", x.sizes());
  torch::Tensor h = x.unsqueeze(1);
  for (std::size_t i = 0; i < convs_->size(); ++i) {
    h = convs_[i]->as<CircularConv1d>()->forward(h);
    if (i + 1 < convs_->size()) h = torch::relu(h);
  }
  return h.flatten(1);
}

std::pair<torch::Tensor, torch::Tensor> VaeEncoderImpl::forward(const torch::Tensor& x) {
  const torch::Tensor features = Features(x);
  return {fc_mu_->forward(features), fc_logvar_->forward(features)};
}

torch::Tensor VaeEncoderImpl::Mu(const torch::Tensor& x) { return fc_mu_->forward(Features(x)); }

}  // namespace colav

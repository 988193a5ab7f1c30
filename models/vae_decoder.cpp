#include "models/vae_decoder.h"

namespace colav {

VaeDecoderImpl::VaeDecoderImpl(VaeDecoderOptions options) : options_(options) {
  TORCH_CHECK(options_.latent_dims > 0, "latent_dims must be positive, got ", options_.latent_dims);
  fc_ = register_module("fc", torch::nn::Linear(options_.latent_dims, kConvFeatureLength));
  deconvs_ = register_module("deconvs", torch::nn::ModuleList());
  for (const ConvLayerSpec& layer : DecoderConvLayers(options_.architecture)) {
    deconvs_->push_back(CircularConvTranspose1d(
        CircularConvTranspose1dOptions(layer.in_channels, layer.out_channels, layer.kernel_size)
            .stride(layer.stride)
            .padding(layer.padding)
            .padding_mode(options_.padding)));
  }
}

torch::Tensor VaeDecoderImpl::forward(const torch::Tensor& z) {
  TORCH_CHECK(z.dim() == 2 && z.size(1) == options_.latent_dims, "decoder expects z of shape [B, ",
              options_.latent_dims, "], got ", z.sizes());
  torch::Tensor h = torch::relu(fc_->forward(z)).unsqueeze(1);
  for (std::size_t i = 0; i < deconvs_->size(); ++i) {
    h = deconvs_[i]->as<CircularConvTranspose1d>()->forward(h);
    if (i + 1 < deconvs_->size()) h = torch::relu(h);
  }
  return torch::sigmoid(h.flatten(1));
}

}  // namespace colav

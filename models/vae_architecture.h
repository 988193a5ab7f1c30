// The two convolution stacks of the paper's VAEs (paper Table "conv_blocks"; spec
// reference-learning 1.2-1.5): Shallow, one circular Conv1d; Deep, three. The decoders use the same
// layers transposed, in reverse order.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace colav {

enum class VaeArchitecture { kShallow, kDeep };

// "shallow" or "deep"; anything else is a UserError naming the value.
VaeArchitecture ParseVaeArchitecture(const std::string& name);
// The inverse of ParseVaeArchitecture.
std::string VaeArchitectureName(VaeArchitecture architecture);

// Rays per scan: the encoder's input and the decoder's output length.
constexpr std::int64_t kScanLength = 180;
// Length of the convolution stack's single-channel output (12 features, 30 degrees apart), the
// input of the latent heads and the output of the decoder's first Linear layer.
constexpr std::int64_t kConvFeatureLength = 12;

// One Conv1d of an encoder stack, padded circularly by `padding` columns at each end.
struct ConvLayerSpec {
  std::int64_t in_channels;
  std::int64_t out_channels;
  std::int64_t kernel_size;
  std::int64_t stride;
  std::int64_t padding;
};

// The encoder's convolutions, input side first; ReLU between consecutive layers, none after the
// last.
std::vector<ConvLayerSpec> EncoderConvLayers(VaeArchitecture architecture);
// The decoder's transposed convolutions, latent side first: the encoder's layers reversed, with
// in and out channels swapped; ReLU between consecutive layers, sigmoid after the last.
std::vector<ConvLayerSpec> DecoderConvLayers(VaeArchitecture architecture);

}  // namespace colav

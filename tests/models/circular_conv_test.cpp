#include "models/circular_conv.h"

#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cstdint>
#include <vector>

#include "tests/models/finite_differences.h"

namespace colav {
namespace {

struct ConvLayer {
  std::int64_t in_channels, out_channels, kernel_size, stride, padding, input_length;
};
// The encoder layers of both architectures.
const std::vector<ConvLayer> kEncoderLayers = {
    {1, 1, 45, 15, 15, 180}, {1, 3, 45, 15, 15, 180}, {3, 2, 3, 1, 1, 12}, {2, 1, 3, 1, 1, 12}};

// Same initialisation (same random draws), outputs and gradients as torch::nn::Conv1d with
// circular padding, the layer of the reference encoder.
TEST(CircularConv1d, MatchesLibTorchsCircularConv1d) {
  for (const ConvLayer& layer : kEncoderLayers) {
    torch::manual_seed(21);
    torch::nn::Conv1d reference(
        torch::nn::Conv1dOptions(layer.in_channels, layer.out_channels, layer.kernel_size)
            .stride(layer.stride)
            .padding(layer.padding)
            .padding_mode(torch::kCircular));
    torch::manual_seed(21);
    CircularConv1d conv(
        CircularConv1dOptions(layer.in_channels, layer.out_channels, layer.kernel_size)
            .stride(layer.stride)
            .padding(layer.padding));
    ASSERT_TRUE(torch::equal(conv->weight, reference->weight));
    ASSERT_TRUE(torch::equal(conv->bias, reference->bias));

    const torch::Tensor x =
        torch::randn({4, layer.in_channels, layer.input_length}).requires_grad_(true);
    const torch::Tensor y = conv(x);
    const torch::Tensor y_reference = reference(x);
    ASSERT_EQ(y.sizes(), y_reference.sizes());
    EXPECT_LT((y - y_reference).abs().max().item<float>(), 1e-5) << "kernel " << layer.kernel_size;

    const torch::Tensor output_weights = torch::randn_like(y);
    const auto gradients =
        torch::autograd::grad({(y * output_weights).sum()}, {x, conv->weight, conv->bias});
    const auto reference_gradients = torch::autograd::grad({(y_reference * output_weights).sum()},
                                                           {x, reference->weight, reference->bias});
    for (std::size_t i = 0; i < gradients.size(); ++i) {
      EXPECT_LT((gradients[i] - reference_gradients[i]).abs().max().item<float>(), 1e-4)
          << "kernel " << layer.kernel_size << ", gradient " << i;
    }
  }
}

TEST(CircularConv1dFunction, BackwardMatchesFiniteDifferences) {
  torch::manual_seed(22);
  for (const ConvLayer& layer : {ConvLayer{2, 3, 45, 15, 15, 180}, ConvLayer{3, 2, 3, 1, 1, 12}}) {
    testing::ExpectGradientsMatchFiniteDifferences(
        [&](const std::vector<torch::Tensor>& inputs) {
          return CircularConv1dFunction::apply(inputs[0], inputs[1], inputs[2], layer.stride,
                                               layer.padding);
        },
        {torch::randn({2, layer.in_channels, layer.input_length}, torch::kFloat64)
             .requires_grad_(true),
         torch::randn({layer.out_channels, layer.in_channels, layer.kernel_size}, torch::kFloat64)
             .requires_grad_(true),
         torch::randn({layer.out_channels}, torch::kFloat64).requires_grad_(true)},
        {"x", "weight", "bias"});
  }
}

TEST(CircularConv1dFunction, RejectsLayersThatDoNotTileTheRing) {
  const torch::Tensor weight = torch::randn({1, 1, 45});
  const torch::Tensor bias = torch::zeros({1});
  // Padding 0: the 45-wide kernel every 15 rays would need 12 - 2 outputs, not 180 / 15.
  EXPECT_THROW(CircularConv1dFunction::apply(torch::randn({1, 1, 180}), weight, bias, 15, 0),
               c10::Error);
  // 170 rays are not a whole number of strides.
  EXPECT_THROW(CircularConv1dFunction::apply(torch::randn({1, 1, 170}), weight, bias, 15, 15),
               c10::Error);
}

}  // namespace
}  // namespace colav

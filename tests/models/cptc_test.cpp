#include "models/cptc.h"

#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cstdint>
#include <vector>

#include "tests/models/finite_differences.h"

namespace colav {
namespace {

namespace F = torch::nn::functional;

// A Conv1d layer shape, in the encoder's direction: in_channels -> out_channels.
struct CptcLayer {
  std::int64_t in_channels, out_channels, kernel_size, stride, padding;
};
constexpr CptcLayer kWideLayer{1, 1, 45, 15, 15};   // the shallow model's layer
constexpr CptcLayer kWideLayer3{1, 3, 45, 15, 15};  // the deep model's first layer
constexpr CptcLayer kNarrowLayer{3, 2, 3, 1, 1};    // the deep model's second layer
constexpr CptcLayer kNarrowLayer2{2, 1, 3, 1, 1};   // the deep model's third layer

// The encoder's circular Conv1d, through LibTorch's own circular padding (an independent oracle).
torch::Tensor CircularConv1d(const torch::Tensor& x, const torch::Tensor& weight,
                             std::int64_t stride, std::int64_t padding) {
  return F::conv1d(F::pad(x, F::PadFuncOptions({padding, padding}).mode(torch::kCircular)), weight,
                   F::Conv1dFuncOptions().stride(stride));
}

torch::Tensor Cptc(const torch::Tensor& z, const torch::Tensor& weight, const torch::Tensor& bias,
                   std::int64_t stride, std::int64_t padding) {
  return CircularConvTranspose1dFunction::apply(z, weight, bias, stride, padding);
}

TEST(CptcWrapWidth, IsOneColumnForThePapersLayers) {
  EXPECT_EQ(CptcWrapWidth(45, 15, 15), 1);
  EXPECT_EQ(CptcWrapWidth(3, 1, 1), 1);
  EXPECT_EQ(CptcWrapWidth(5, 1, 2), 2);
}

// With tied weights, CPTC is the adjoint of the circular Conv1d: CPTC(z) = J^T z, the
// vector-Jacobian product of the convolution. Checked for every layer shape of both decoders.
TEST(CircularConvTranspose1dFunction, EqualsTheAdjointOfTheCircularConv1d) {
  torch::manual_seed(1);
  for (const CptcLayer& layer : {kWideLayer, kWideLayer3, kNarrowLayer, kNarrowLayer2}) {
    const std::int64_t input_length = layer.stride == 15 ? 180 : 12;
    const torch::Tensor weight =
        torch::randn({layer.out_channels, layer.in_channels, layer.kernel_size}, torch::kFloat64);
    const torch::Tensor x =
        torch::randn({3, layer.in_channels, input_length}, torch::kFloat64).requires_grad_(true);
    const torch::Tensor y = CircularConv1d(x, weight, layer.stride, layer.padding);
    const torch::Tensor z = torch::randn_like(y);
    const torch::Tensor vjp = torch::autograd::grad({y}, {x}, {z})[0];

    const torch::Tensor cptc = Cptc(z, weight, torch::zeros({layer.in_channels}, torch::kFloat64),
                                    layer.stride, layer.padding);
    ASSERT_EQ(cptc.sizes(), vjp.sizes());
    EXPECT_LT((cptc - vjp).abs().max().item<double>(), 1e-12)
        << "kernel " << layer.kernel_size << ", channels " << layer.in_channels << "<-"
        << layer.out_channels;
  }
}

// x̂[n] = b + sum_i sum_k w[k] z[i] 1[(15 i + k - 15) mod 180 = n] (spec reference-learning 2.3).
TEST(CircularConvTranspose1dFunction, MatchesTheIndexFormula) {
  torch::manual_seed(2);
  const torch::Tensor z = torch::randn({1, 1, 12}, torch::kFloat64);
  const torch::Tensor weight = torch::randn({1, 1, 45}, torch::kFloat64);
  const torch::Tensor bias = torch::randn({1}, torch::kFloat64);
  std::vector<double> expected(180, bias.item<double>());
  for (int i = 0; i < 12; ++i) {
    for (int k = 0; k < 45; ++k) {
      expected[((15 * i + k - 15) % 180 + 180) % 180] +=
          weight[0][0][k].item<double>() * z[0][0][i].item<double>();
    }
  }
  const torch::Tensor output = Cptc(z, weight, bias, 15, 15);
  for (int n = 0; n < 180; ++n) {
    EXPECT_NEAR(output[0][0][n].item<double>(), expected[n], 1e-12) << "n = " << n;
  }
}

// The paper's recipe, literally: wrap CptcWrapWidth columns from the opposite ends, apply
// ConvTranspose1d with its own padding, crop that many strides at each end.
TEST(CircularConvTranspose1dFunction, EqualsWrapTransposeAndCrop) {
  torch::manual_seed(12);
  for (const CptcLayer& layer : {kWideLayer, kWideLayer3, kNarrowLayer, kNarrowLayer2}) {
    const std::int64_t wrap = CptcWrapWidth(layer.kernel_size, layer.stride, layer.padding);
    const torch::Tensor z = torch::randn({3, layer.out_channels, 12}, torch::kFloat64);
    const torch::Tensor weight =
        torch::randn({layer.out_channels, layer.in_channels, layer.kernel_size}, torch::kFloat64);
    const torch::Tensor bias = torch::randn({layer.in_channels}, torch::kFloat64);
    const torch::Tensor wrapped =
        torch::cat({z.narrow(2, 12 - wrap, wrap), z, z.narrow(2, 0, wrap)}, 2);
    const torch::Tensor transposed = F::conv_transpose1d(
        wrapped, weight,
        F::ConvTranspose1dFuncOptions().bias(bias).stride(layer.stride).padding(layer.padding));
    const torch::Tensor recipe =
        transposed.narrow(2, wrap * layer.stride, transposed.size(2) - 2 * wrap * layer.stride);
    const torch::Tensor cptc = Cptc(z, weight, bias, layer.stride, layer.padding);
    ASSERT_EQ(cptc.sizes(), recipe.sizes());
    EXPECT_LT((cptc - recipe).abs().max().item<double>(), 1e-12) << "kernel " << layer.kernel_size;
  }
}

// The "true circular" rows of the fixture table in spec reference-learning 2.3.
TEST(CircularConvTranspose1dFunction, ReproducesTheTrueCircularFixtureTable) {
  const torch::Tensor z = torch::arange(1, 13, torch::kFloat64).view({1, 1, 12});
  const torch::Tensor bias = torch::zeros({1}, torch::kFloat64);
  const std::vector<int> n = {0, 7, 14, 15, 29, 90, 164, 165, 172, 179};
  const std::vector<double> ones_row = {15, 15, 15, 6, 6, 21, 33, 24, 24, 24};
  const std::vector<double> ramp_row = {375, 480, 585, 60, 144, 285, 927, 510, 678, 846};

  const torch::Tensor ones = Cptc(z, torch::ones({1, 1, 45}, torch::kFloat64), bias, 15, 15);
  const torch::Tensor ramp =
      Cptc(z, torch::arange(45, torch::kFloat64).view({1, 1, 45}), bias, 15, 15);
  for (std::size_t i = 0; i < n.size(); ++i) {
    EXPECT_DOUBLE_EQ(ones[0][0][n[i]].item<double>(), ones_row[i]) << "w = 1, n = " << n[i];
    EXPECT_DOUBLE_EQ(ramp[0][0][n[i]].item<double>(), ramp_row[i]) << "w = k, n = " << n[i];
  }
}

// Central differences against the explicit backward, for every entry of z, weight and bias.
void ExpectBackwardMatchesFiniteDifferences(std::int64_t in_channels, std::int64_t out_channels,
                                            std::int64_t kernel_size, std::int64_t stride,
                                            std::int64_t padding) {
  torch::manual_seed(3);
  testing::ExpectGradientsMatchFiniteDifferences(
      [&](const std::vector<torch::Tensor>& inputs) {
        return Cptc(inputs[0], inputs[1], inputs[2], stride, padding);
      },
      {torch::randn({2, in_channels, 12}, torch::kFloat64).requires_grad_(true),
       torch::randn({in_channels, out_channels, kernel_size}, torch::kFloat64).requires_grad_(true),
       torch::randn({out_channels}, torch::kFloat64).requires_grad_(true)},
      {"z", "weight", "bias"});
}

TEST(CircularConvTranspose1dFunction, BackwardMatchesFiniteDifferencesWideLayer) {
  ExpectBackwardMatchesFiniteDifferences(2, 3, 45, 15, 15);
}

TEST(CircularConvTranspose1dFunction, BackwardMatchesFiniteDifferencesNarrowLayer) {
  ExpectBackwardMatchesFiniteDifferences(3, 2, 3, 1, 1);
}

// The backward skips the gradients nobody asked for and still gets the others right.
TEST(CircularConvTranspose1dFunction, GradientOfTheWeightAloneMatchesTheFullBackward) {
  torch::manual_seed(4);
  const torch::Tensor z = torch::randn({4, 2, 12}, torch::kFloat64);
  const torch::Tensor weight = torch::randn({2, 3, 45}, torch::kFloat64).requires_grad_(true);
  const torch::Tensor bias = torch::randn({3}, torch::kFloat64);
  const torch::Tensor weight_only =
      torch::autograd::grad({Cptc(z, weight, bias, 15, 15).square().sum()}, {weight})[0];
  const torch::Tensor z_variable = z.clone().requires_grad_(true);
  const torch::Tensor full = torch::autograd::grad(
      {Cptc(z_variable, weight, bias, 15, 15).square().sum()}, {z_variable, weight})[1];
  EXPECT_TRUE(torch::allclose(weight_only, full));
}

TEST(CircularConvTranspose1d, OutputLengthIsStrideTimesInputLength) {
  struct Case {
    CircularConvTranspose1dOptions options;
    std::int64_t expected_length;
  };
  for (DecoderPadding padding : {DecoderPadding::kCircular, DecoderPadding::kZero}) {
    const std::vector<Case> cases = {
        {CircularConvTranspose1dOptions(1, 1, 45).stride(15).padding(15).padding_mode(padding),
         180},
        {CircularConvTranspose1dOptions(3, 1, 45).stride(15).padding(15).padding_mode(padding),
         180},
        {CircularConvTranspose1dOptions(1, 2, 3).stride(1).padding(1).padding_mode(padding), 12},
        {CircularConvTranspose1dOptions(2, 3, 3).stride(1).padding(1).padding_mode(padding), 12}};
    for (const Case& c : cases) {
      CircularConvTranspose1d layer(c.options);
      const torch::Tensor output = layer(torch::randn({4, c.options.in_channels(), 12}));
      EXPECT_EQ(output.sizes(),
                (std::vector<std::int64_t>{4, c.options.out_channels(), c.expected_length}));
    }
  }
}

// Rolling the latent by one column rolls the output by one stride, across the seam at ray 0, only
// with circular padding.
TEST(CircularConvTranspose1d, IsShiftEquivariantOnlyWithCircularPadding) {
  for (const auto& [in_channels, out_channels, kernel, stride, padding] :
       {kWideLayer, kNarrowLayer2}) {
    torch::manual_seed(5);
    const auto options = CircularConvTranspose1dOptions(out_channels, in_channels, kernel)
                             .stride(stride)
                             .padding(padding);
    CircularConvTranspose1d circular(options);
    CircularConvTranspose1d zero(
        CircularConvTranspose1dOptions(options).padding_mode(DecoderPadding::kZero));
    torch::NoGradGuard no_grad;
    zero->weight.copy_(circular->weight);
    zero->bias.copy_(circular->bias);

    const torch::Tensor z = torch::rand({2, out_channels, 12}) + 0.5;
    const torch::Tensor rolled = z.roll(1, 2);
    EXPECT_LT((circular(rolled) - circular(z).roll(stride, 2)).abs().max().item<float>(), 1e-5)
        << "kernel " << kernel;
    EXPECT_GT((zero(rolled) - zero(z).roll(stride, 2)).abs().max().item<float>(), 1e-2)
        << "kernel " << kernel;
  }
}

TEST(CircularConvTranspose1d, ZeroPaddingIsAPlainConvTranspose1d) {
  CircularConvTranspose1d layer(
      CircularConvTranspose1dOptions(3, 1, 45).stride(15).padding(15).padding_mode(
          DecoderPadding::kZero));
  torch::nn::ConvTranspose1d reference(
      torch::nn::ConvTranspose1dOptions(3, 1, 45).stride(15).padding(15));
  {
    torch::NoGradGuard no_grad;
    reference->weight.copy_(layer->weight);
    reference->bias.copy_(layer->bias);
  }
  const torch::Tensor z = torch::randn({4, 3, 12});
  EXPECT_TRUE(torch::allclose(layer(z), reference(z)));
}

TEST(CircularConvTranspose1d, InitialisesLikeConvTranspose1d) {
  torch::manual_seed(6);
  torch::nn::ConvTranspose1d reference(
      torch::nn::ConvTranspose1dOptions(2, 3, 45).stride(15).padding(15));
  torch::manual_seed(6);
  CircularConvTranspose1d layer(CircularConvTranspose1dOptions(2, 3, 45).stride(15).padding(15));
  EXPECT_TRUE(torch::equal(layer->weight, reference->weight));
  EXPECT_TRUE(torch::equal(layer->bias, reference->bias));
  EXPECT_EQ(layer->named_parameters().size(), 2u);
}

TEST(CircularConvTranspose1dFunction, RejectsALayerThatDoesNotTileTheCircle) {
  const torch::Tensor z = torch::randn({1, 1, 12});
  EXPECT_THROW(Cptc(z, torch::randn({1, 1, 45}), torch::zeros({1}), 15, 0), c10::Error);
}

}  // namespace
}  // namespace colav

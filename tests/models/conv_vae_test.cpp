#include "models/conv_vae.h"

#include <ATen/CPUGeneratorImpl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "models/circular_conv.h"
#include "models/vae_architecture.h"
#include "models/vae_loss.h"
#include "src/error.h"

namespace colav {
namespace {

// The weights LibTorch's own initialisers draw from the global generator, for
// ResetConvolutionParameters to match with an explicit one.
TEST(ResetConvolutionParametersTest, DrawsWhatTorchNnInitDrawsFromTheSameState) {
  for (const std::vector<std::int64_t>& shape :
       std::vector<std::vector<std::int64_t>>{{12, 180}, {16, 1, 5}, {8, 4, 3}}) {
    torch::manual_seed(7);
    torch::Tensor expected_weight = torch::empty(shape);
    torch::Tensor expected_bias = torch::empty({shape[0]});
    torch::nn::init::kaiming_uniform_(expected_weight, std::sqrt(5.0));
    const double bound = 1.0 / std::sqrt(static_cast<double>(expected_weight[0].numel()));
    torch::nn::init::uniform_(expected_bias, -bound, bound);

    torch::Tensor weight = torch::empty(shape);
    torch::Tensor bias = torch::empty({shape[0]});
    ResetConvolutionParameters(weight, bias, at::make_generator<at::CPUGeneratorImpl>(7));
    EXPECT_TRUE(torch::equal(weight, expected_weight)) << torch::IntArrayRef(shape);
    EXPECT_TRUE(torch::equal(bias, expected_bias)) << torch::IntArrayRef(shape);
  }
}

TEST(RedrawLayerParametersTest, GivesTheWeightsTheConstructorsDrawFromTheSeededGlobalGenerator) {
  for (const VaeArchitecture architecture : {VaeArchitecture::kShallow, VaeArchitecture::kDeep}) {
    for (const DecoderPadding padding : {DecoderPadding::kCircular, DecoderPadding::kZero}) {
      const VaeOptions options{architecture, 12, padding};
      torch::manual_seed(11);
      const ConvVae expected(options);
      ConvVae vae(options);
      torch::Generator generator = at::make_generator<at::CPUGeneratorImpl>(11);
      RedrawLayerParameters(*vae, generator);
      const std::vector<torch::Tensor> expected_parameters = expected->parameters();
      const std::vector<torch::Tensor> parameters = vae->parameters();
      ASSERT_EQ(parameters.size(), expected_parameters.size());
      for (std::size_t i = 0; i < parameters.size(); ++i) {
        EXPECT_TRUE(torch::equal(parameters[i], expected_parameters[i])) << i;
      }
    }
  }
}

std::int64_t ParameterCount(const torch::nn::Module& module) {
  std::int64_t count = 0;
  for (const torch::Tensor& parameter : module.parameters()) count += parameter.numel();
  return count;
}

TEST(ParseVaeArchitecture, ParsesBothNamesAndRejectsOthersByName) {
  EXPECT_EQ(ParseVaeArchitecture("shallow"), VaeArchitecture::kShallow);
  EXPECT_EQ(ParseVaeArchitecture("deep"), VaeArchitecture::kDeep);
  EXPECT_EQ(VaeArchitectureName(VaeArchitecture::kDeep), "deep");
  try {
    ParseVaeArchitecture("Deep");
    FAIL() << "expected UserError";
  } catch (const UserError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("'Deep'"));
  }
}

TEST(DecoderConvLayers, AreTheEncoderLayersTransposedInReverseOrder) {
  const std::vector<ConvLayerSpec> layers = DecoderConvLayers(VaeArchitecture::kDeep);
  ASSERT_EQ(layers.size(), 3u);
  // CPTC(1->2, k3, s1, p1), CPTC(2->3, k3, s1, p1), CPTC(3->1, k45, s15, p15).
  const std::vector<std::vector<std::int64_t>> expected = {
      {1, 2, 3, 1, 1}, {2, 3, 3, 1, 1}, {3, 1, 45, 15, 15}};
  for (std::size_t i = 0; i < layers.size(); ++i) {
    EXPECT_EQ(
        (std::vector<std::int64_t>{layers[i].in_channels, layers[i].out_channels,
                                   layers[i].kernel_size, layers[i].stride, layers[i].padding}),
        expected[i])
        << "layer " << i;
  }
}

// Orientation of the circular Conv1d (spec reference-learning 1.2 and 2.3): w[k] = k, x[n] = n,
// no bias.
TEST(VaeEncoder, CircularConvolutionHasTheReferenceOrientation) {
  VaeEncoder encoder(VaeEncoderOptions{VaeArchitecture::kShallow, 12});
  encoder->to(torch::kFloat64);
  {
    torch::NoGradGuard no_grad;
    auto parameters = encoder->named_parameters();
    parameters["convs.0.weight"].copy_(torch::arange(45).view({1, 1, 45}));
    parameters["convs.0.bias"].zero_();
  }
  const torch::Tensor features =
      encoder->Features(torch::arange(180, torch::kFloat64).view({1, 180}));
  EXPECT_DOUBLE_EQ(features[0][0].item<double>(), 33420);
  EXPECT_DOUBLE_EQ(features[0][1].item<double>(), 29370);
  EXPECT_DOUBLE_EQ(features[0][2].item<double>(), 44220);
}

// Without a ReLU on the heads, mu and logvar can be negative (a posterior narrower than the prior).
TEST(VaeEncoder, HeadsHaveNoRelu) {
  VaeEncoder encoder(VaeEncoderOptions{VaeArchitecture::kDeep, 12});
  {
    torch::NoGradGuard no_grad;
    auto parameters = encoder->named_parameters();
    for (const char* head : {"fc_mu", "fc_logvar"}) {
      parameters[std::string(head) + ".weight"].zero_();
      parameters[std::string(head) + ".bias"].fill_(-0.5);
    }
  }
  const torch::Tensor x = torch::rand({3, 180});
  const auto [mu, logvar] = encoder(x);
  EXPECT_TRUE(torch::equal(mu, torch::full({3, 12}, -0.5)));
  EXPECT_TRUE(torch::equal(logvar, torch::full({3, 12}, -0.5)));
  EXPECT_TRUE(torch::equal(encoder->Mu(x), mu));
}

TEST(VaeEncoder, RejectsScansOfTheWrongLength) {
  VaeEncoder encoder(VaeEncoderOptions{});
  EXPECT_THROW(encoder(torch::zeros({2, 179})), c10::Error);
}

struct ParameterCounts {
  VaeArchitecture architecture;
  std::int64_t latent_dims, encoder, decoder;
};

// Spec reference-learning 1.2-1.5 with the ReLU-free heads: Linear heads and the decoder's Linear
// scale with the latent size, the convolutions do not.
TEST(ConvVae, HasTheSpecifiedParameterCounts) {
  for (const ParameterCounts& expected :
       {ParameterCounts{VaeArchitecture::kShallow, 12, 358, 202},
        ParameterCounts{VaeArchitecture::kDeep, 12, 477, 321},
        ParameterCounts{VaeArchitecture::kShallow, 2, 46 + 2 * 26, 36 + 46},
        ParameterCounts{VaeArchitecture::kDeep, 2, 165 + 2 * 26, 36 + 165}}) {
    for (DecoderPadding padding : {DecoderPadding::kCircular, DecoderPadding::kZero}) {
      ConvVae vae(VaeOptions{expected.architecture, expected.latent_dims, padding});
      const std::string name = VaeArchitectureName(expected.architecture) + " latent " +
                               std::to_string(expected.latent_dims);
      EXPECT_EQ(ParameterCount(*vae->encoder()), expected.encoder) << name;
      EXPECT_EQ(ParameterCount(*vae->decoder()), expected.decoder) << name;
      EXPECT_EQ(ParameterCount(*vae), expected.encoder + expected.decoder) << name;
    }
  }
}

TEST(ConvVae, ForwardShapesAndRangeForBothArchitecturesAndLatentSizes) {
  torch::manual_seed(7);
  const torch::Tensor x = torch::rand({5, 180});
  for (VaeArchitecture architecture : {VaeArchitecture::kShallow, VaeArchitecture::kDeep}) {
    for (std::int64_t latent_dims : {12, 2}) {
      for (DecoderPadding padding : {DecoderPadding::kCircular, DecoderPadding::kZero}) {
        ConvVae vae(VaeOptions{architecture, latent_dims, padding});
        const ConvVaeImpl::Output output = vae(x, at::make_generator<at::CPUGeneratorImpl>(1));
        const std::string name =
            VaeArchitectureName(architecture) + " latent " + std::to_string(latent_dims);
        EXPECT_EQ(output.reconstruction.sizes(), (std::vector<std::int64_t>{5, 180})) << name;
        EXPECT_EQ(output.mu.sizes(), (std::vector<std::int64_t>{5, latent_dims})) << name;
        EXPECT_EQ(output.logvar.sizes(), (std::vector<std::int64_t>{5, latent_dims})) << name;
        EXPECT_GT(output.reconstruction.min().item<float>(), 0) << name;
        EXPECT_LT(output.reconstruction.max().item<float>(), 1) << name;
      }
    }
  }
}

// forward decodes z = mu + eps * exp(logvar / 2) with eps drawn from the given generator.
TEST(ConvVae, SamplesTheLatentFromTheGivenGenerator) {
  torch::manual_seed(8);
  ConvVae vae(VaeOptions{VaeArchitecture::kDeep, 12, DecoderPadding::kCircular});
  const torch::Tensor x = torch::rand({4, 180});

  const ConvVaeImpl::Output first = vae(x, at::make_generator<at::CPUGeneratorImpl>(11));
  const ConvVaeImpl::Output again = vae(x, at::make_generator<at::CPUGeneratorImpl>(11));
  const ConvVaeImpl::Output other = vae(x, at::make_generator<at::CPUGeneratorImpl>(12));
  EXPECT_TRUE(torch::equal(first.reconstruction, again.reconstruction));
  EXPECT_FALSE(torch::allclose(first.reconstruction, other.reconstruction));

  const torch::Tensor eps =
      torch::randn({4, 12}, at::make_generator<at::CPUGeneratorImpl>(11), torch::kFloat32);
  const torch::Tensor expected = vae->decoder()(first.mu + eps * torch::exp(0.5 * first.logvar));
  EXPECT_TRUE(torch::allclose(first.reconstruction, expected, 1e-6, 1e-7));
}

// Every parameter of encoder and decoder (CPTC included) receives a gradient from the loss.
TEST(ConvVae, LossGradientReachesEveryParameter) {
  for (VaeArchitecture architecture : {VaeArchitecture::kShallow, VaeArchitecture::kDeep}) {
    torch::manual_seed(10);
    ConvVae vae(VaeOptions{architecture, 12, DecoderPadding::kCircular});
    const torch::Tensor x = torch::rand({8, 180});
    ComputeVaeLoss(vae(x, at::make_generator<at::CPUGeneratorImpl>(1)), x, 1.0).total.backward();
    for (const auto& parameter : vae->named_parameters()) {
      ASSERT_TRUE(parameter.value().grad().defined()) << parameter.key();
      EXPECT_GT(parameter.value().grad().abs().sum().item<float>(), 0) << parameter.key();
    }
  }
}

}  // namespace
}  // namespace colav

#include "models/feature_extractor.h"

#include <gtest/gtest.h>

#include <string>

#include "env/environment_spec.h"
#include "models/torchscript_export.h"
#include "src/error.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::UserErrorMessage;

std::filesystem::path ExportedEncoder(const std::filesystem::path& folder,
                                      VaeArchitecture architecture, std::int64_t latent) {
  const std::filesystem::path path = folder / "encoder.pt";
  ExportEncoder(VaeEncoder(VaeEncoderOptions{architecture, latent}), ObservationSettings{}, path);
  return path;
}

TEST(FeatureExtractorTest, BaselineIsOneCircularConvAfterTheNavigationValues) {
  FeatureExtractor extractor(FeatureExtractorOptions{});
  ASSERT_EQ(extractor->features_dim(), 18);
  const torch::Tensor obs = torch::rand({2, kObservationSize});
  const torch::Tensor features = extractor->forward(obs).detach();
  EXPECT_TRUE(
      torch::equal(features.narrow(1, 0, kNavigationSize), obs.narrow(1, 0, kNavigationSize)));
  // y[l] = b + sum_k w[k] x[(15 l + k - 15) mod 180], no activation.
  const torch::Tensor w = extractor->layers()[0].conv->weight.detach().flatten();
  const float b = extractor->layers()[0].conv->bias.item<float>();
  for (int l = 0; l < 12; ++l) {
    double y = b;
    for (int k = 0; k < 45; ++k) {
      const int ray = ((15 * l + k - 15) % 180 + 180) % 180;
      y += w[k].item<double>() * obs[1][kNavigationSize + ray].item<double>();
    }
    EXPECT_NEAR(features[1][kNavigationSize + l].item<double>(), y, 1e-5) << l;
  }
  EXPECT_TRUE(extractor->trainable());
}

// Observations [B, 6 + 180 * scans.size()]: random navigation values, then the scans [B, 180].
torch::Tensor ObservationOf(const std::vector<torch::Tensor>& scans) {
  std::vector<torch::Tensor> parts = {torch::rand({scans.front().size(0), kNavigationSize})};
  parts.insert(parts.end(), scans.begin(), scans.end());
  return torch::cat(parts, 1);
}

TEST(FeatureExtractorTest, EachScanIsEncodedByTheSameStackInOrder) {
  FeatureExtractorOptions options;
  options.scans = 3;
  options.baseline_convs = ParseConvStack("3:45:15:15,1:3:1:1");  // two layers, a ReLU between
  FeatureExtractor extractor(options);
  ASSERT_EQ(extractor->observation_size(), kNavigationSize + 3 * kNumRays);
  ASSERT_EQ(extractor->features_dim(), kNavigationSize + 3 * 12);
  torch::NoGradGuard no_grad;
  const torch::Tensor a = torch::rand({2, kNumRays});
  const torch::Tensor b = torch::rand({2, kNumRays});
  const torch::Tensor c = torch::rand({2, kNumRays});
  const auto block = [](const torch::Tensor& features, int k) {
    return features.narrow(1, kNavigationSize + 12 * k, 12);
  };

  const torch::Tensor copies = ObservationOf({a, a, a});
  const torch::Tensor features = extractor->forward(copies);
  EXPECT_TRUE(
      torch::equal(features.narrow(1, 0, kNavigationSize), copies.narrow(1, 0, kNavigationSize)));
  const torch::Tensor encoding = extractor->Perception(a);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(torch::allclose(block(features, k), encoding)) << k;

  const torch::Tensor abc = extractor->forward(ObservationOf({a, b, c}));
  const torch::Tensor cab = extractor->forward(ObservationOf({c, a, b}));
  EXPECT_FALSE(torch::allclose(block(abc, 0), block(abc, 1)));  // distinct scans, distinct codes
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(torch::allclose(block(cab, (k + 1) % 3), block(abc, k)));
}

TEST(FeatureExtractorTest, ObservationsOfAnotherWidthAreRejected) {
  FeatureExtractorOptions options;
  options.scans = 3;
  FeatureExtractor extractor(options);
  try {
    extractor->forward(torch::rand({2, kObservationSize}));
    ADD_FAILURE() << "a single-scan observation was accepted";
  } catch (const c10::Error& error) {
    EXPECT_NE(std::string(error.what_without_backtrace()).find("[B, 546]"), std::string::npos)
        << error.what_without_backtrace();
  }
  EXPECT_THROW(extractor->forward(torch::rand({2, kNavigationSize + 4 * kNumRays})), c10::Error);
  EXPECT_THROW(FeatureExtractor(FeatureExtractorOptions{})->forward(torch::rand({2, 546})),
               c10::Error);
  options.scans = 0;
  EXPECT_THROW(FeatureExtractor{options}, c10::Error);
}

TEST(FeatureExtractorTest, UnknownExtractorNameIsAOneLineUserError) {
  const std::string message = UserErrorMessage([] { ParseExtractorKind("vae-huge"); });
  EXPECT_NE(message.find("vae-huge"), std::string::npos);
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(FeatureExtractorTest, MissingEncoderFileIsAUserErrorNamingIt) {
  FeatureExtractorOptions options;
  options.kind = ExtractorKind::kVaeShallow;
  options.encoder = "/nonexistent/encoder.pt";
  const std::string message = UserErrorMessage([&] { FeatureExtractor extractor(options); });
  EXPECT_NE(message.find("/nonexistent/encoder.pt"), std::string::npos) << message;
}

TEST(FeatureExtractorTest, EncoderOfTheWrongLatentSizeIsAUserErrorNamingTheFile) {
  testing_util::TemporaryFolder directory;
  FeatureExtractorOptions options;
  options.kind = ExtractorKind::kVaeShallow;
  options.encoder = ExportedEncoder(directory.path(), VaeArchitecture::kShallow, 8);
  const std::string message = UserErrorMessage([&] { FeatureExtractor extractor(options); });
  EXPECT_NE(message.find(options.encoder.string()), std::string::npos) << message;
  EXPECT_NE(message.find("latent size 8"), std::string::npos) << message;
  options.latent_dims = 8;  // configured: accepted
  FeatureExtractor extractor(options);
  EXPECT_EQ(extractor->features_dim(), kNavigationSize + 8);
}

TEST(FeatureExtractorTest, EncoderOfTheWrongArchitectureIsAUserError) {
  testing_util::TemporaryFolder directory;
  FeatureExtractorOptions options;
  options.kind = ExtractorKind::kVaeShallow;
  options.encoder = ExportedEncoder(directory.path(), VaeArchitecture::kDeep, 12);
  const std::string message = UserErrorMessage([&] { FeatureExtractor extractor(options); });
  EXPECT_NE(message.find("deep"), std::string::npos) << message;
}

TEST(FeatureExtractorTest, LockedEncoderDoesNotTrain) {
  testing_util::TemporaryFolder directory;
  FeatureExtractorOptions options;
  options.kind = ExtractorKind::kVaeShallow;
  options.encoder = ExportedEncoder(directory.path(), VaeArchitecture::kShallow, 12);
  FeatureExtractor locked(options);
  EXPECT_FALSE(locked->trainable());
  for (const auto& parameter : locked->parameters()) EXPECT_FALSE(parameter.requires_grad());
  options.locked = false;
  FeatureExtractor unlocked(options);
  EXPECT_TRUE(unlocked->trainable());
  for (const auto& parameter : unlocked->parameters()) EXPECT_TRUE(parameter.requires_grad());
}

TEST(FeatureExtractorTest, ConvStackSpecs) {
  const auto layers = ParseConvStack("3:45:15:15,1:3:1:1");
  ASSERT_EQ(layers.size(), 2U);
  EXPECT_EQ(layers[1].in_channels, 3);
  EXPECT_EQ(layers[1].kernel_size, 3);
  FeatureExtractorOptions options;
  options.baseline_convs = layers;
  EXPECT_EQ(FeatureExtractor(options)->features_dim(), kNavigationSize + 12);
  for (const char* bad :
       {"", "1:45:15", "1:45:15:15:1", "1:0:15:15", "1:45:15:15,", "a:b:c:d", "1:400:1:0"}) {
    EXPECT_NE(UserErrorMessage([&] { ParseConvStack(bad); }), "<no UserError>") << bad;
  }
}

}  // namespace
}  // namespace colav

#include "models/torchscript_export.h"

#include <ATen/CPUGeneratorImpl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <torch/script.h>
#include <torch/torch.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "models/conv_vae.h"
#include "src/error.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::HasSubstr;
using testing_util::TemporaryFolder;

// A batch of scans with structure at both ends of the ring.
torch::Tensor Scans() {
  const torch::Tensor angle = torch::arange(180, torch::kFloat32) * (2 * M_PI / 180);
  return torch::stack({0.5 + 0.4 * torch::cos(angle), 0.5 + 0.4 * torch::sin(3 * angle),
                       torch::zeros({180}), torch::rand({180})});
}

float MaxAbsDifference(const torch::Tensor& a, const torch::Tensor& b) {
  return (a - b).abs().max().item<float>();
}

using testing_util::UserErrorMessage;

struct Configuration {
  VaeArchitecture architecture;
  std::int64_t latent_dims;
  DecoderPadding padding;
};

const std::vector<Configuration> kConfigurations = {
    {VaeArchitecture::kShallow, 12, DecoderPadding::kCircular},
    {VaeArchitecture::kDeep, 12, DecoderPadding::kCircular},
    {VaeArchitecture::kShallow, 2, DecoderPadding::kZero},
    {VaeArchitecture::kDeep, 2, DecoderPadding::kZero}};

TEST(ExportEncoder, LoadedModuleGivesTheSameMuAndCarriesItsAttributes) {
  TemporaryFolder directory;
  const torch::Tensor x = Scans();
  for (const Configuration& configuration : kConfigurations) {
    VaeEncoder encoder(VaeEncoderOptions{configuration.architecture, configuration.latent_dims});
    const std::filesystem::path path = directory.path() / "encoder.pt";
    ExportEncoder(encoder, ObservationSettings{ClosenessTransform::kLog}, path);

    torch::jit::Module loaded = torch::jit::load(path.string());
    const torch::Tensor mu = loaded.forward({x}).toTensor();
    torch::NoGradGuard no_grad;
    EXPECT_LE(MaxAbsDifference(mu, encoder->Mu(x)), 1e-6);
    EXPECT_EQ(loaded.attr("architecture").toStringRef(),
              VaeArchitectureName(configuration.architecture));
    EXPECT_EQ(loaded.attr("latent_dims").toInt(), configuration.latent_dims);
    EXPECT_EQ(EncoderObservationSettings(path), ObservationSettings{ClosenessTransform::kLog});
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory.path()),
                            std::filesystem::directory_iterator()),
              1);  // no temporary file left beside it
  }
}

// With logvar pinned far below zero the sampling noise vanishes, so the scripted forward must
// reproduce the C++ reconstruction.
TEST(ExportVae, LoadedModuleReproducesReconstructionMuAndLogvar) {
  TemporaryFolder directory;
  const torch::Tensor x = Scans();
  for (const Configuration& configuration : kConfigurations) {
    ConvVae vae(
        VaeOptions{configuration.architecture, configuration.latent_dims, configuration.padding});
    {
      torch::NoGradGuard no_grad;
      auto parameters = vae->named_parameters();
      parameters["encoder.fc_logvar.weight"].zero_();
      parameters["encoder.fc_logvar.bias"].fill_(-80);
    }
    const std::filesystem::path path = directory.path() / "vae.pt";
    ExportVae(vae, ObservationSettings{}, path);

    torch::jit::Module loaded = torch::jit::load(path.string());
    const auto outputs = loaded.forward({x}).toTuple()->elements();
    ASSERT_EQ(outputs.size(), 3u);
    torch::NoGradGuard no_grad;
    const ConvVaeImpl::Output expected = vae(x, at::make_generator<at::CPUGeneratorImpl>(1));
    EXPECT_LE(MaxAbsDifference(outputs[0].toTensor(), expected.reconstruction), 1e-6);
    EXPECT_LE(MaxAbsDifference(outputs[1].toTensor(), expected.mu), 1e-6);
    EXPECT_LE(MaxAbsDifference(outputs[2].toTensor(), expected.logvar), 1e-6);

    const torch::Tensor z = torch::randn({4, configuration.latent_dims});
    EXPECT_LE(MaxAbsDifference(loaded.get_method("decode")({z}).toTensor(), vae->decoder()(z)),
              1e-6);
    EXPECT_EQ(loaded.attr("decoder_padding").toStringRef(),
              configuration.padding == DecoderPadding::kCircular ? "circular" : "zero");
  }
}

TEST(ExportVae, ScriptedForwardSamplesTheLatent) {
  TemporaryFolder directory;
  ConvVae vae(VaeOptions{});
  ExportVae(vae, ObservationSettings{}, directory.path() / "vae.pt");
  torch::jit::Module loaded = torch::jit::load((directory.path() / "vae.pt").string());
  const torch::Tensor x = Scans();
  const torch::Tensor first = loaded.forward({x}).toTuple()->elements()[0].toTensor();
  const torch::Tensor second = loaded.forward({x}).toTuple()->elements()[0].toTensor();
  EXPECT_FALSE(torch::equal(first, second));
}

TEST(ExportEncoder, UnwritablePathIsAUserError) {
  TemporaryFolder directory;
  const std::filesystem::path not_a_folder = directory.path() / "file";
  std::ofstream(not_a_folder) << "a file, not a folder\n";
  VaeEncoder encoder(VaeEncoderOptions{});
  EXPECT_THAT(UserErrorMessage([&] {
                ExportEncoder(encoder, ObservationSettings{}, not_a_folder / "encoder.pt");
              }),
              HasSubstr(not_a_folder.string()));
}

TEST(LoadVaeEncoder, RebuildsTheExportedEncoder) {
  TemporaryFolder directory;
  const torch::Tensor x = Scans();
  for (const Configuration& configuration : kConfigurations) {
    VaeEncoder encoder(VaeEncoderOptions{configuration.architecture, configuration.latent_dims});
    ExportEncoder(encoder, ObservationSettings{}, directory.path() / "encoder.pt");
    VaeEncoder loaded = LoadVaeEncoder(directory.path() / "encoder.pt");
    EXPECT_EQ(loaded->options().architecture, configuration.architecture);
    EXPECT_EQ(loaded->options().latent_dims, configuration.latent_dims);
    const auto original_parameters = encoder->named_parameters();
    for (const auto& parameter : loaded->named_parameters()) {
      EXPECT_TRUE(torch::equal(parameter.value(), original_parameters[parameter.key()]))
          << parameter.key();
    }
    torch::NoGradGuard no_grad;
    EXPECT_TRUE(torch::equal(loaded->Mu(x), encoder->Mu(x)));
  }
}

TEST(LoadVaeEncoder, MissingFileIsAUserErrorNamingIt) {
  TemporaryFolder directory;
  const std::filesystem::path path = directory.path() / "absent.pt";
  EXPECT_THAT(UserErrorMessage([&] { LoadVaeEncoder(path); }),
              HasSubstr("'" + path.string() + "' does not exist"));
}

TEST(LoadVaeEncoder, GarbageFileIsAUserErrorNamingIt) {
  TemporaryFolder directory;
  const std::filesystem::path path = directory.path() / "garbage.pt";
  std::ofstream(path) << "this is not a zip archive\n";
  EXPECT_THAT(UserErrorMessage([&] { LoadVaeEncoder(path); }),
              HasSubstr("'" + path.string() + "' is not a TorchScript file"));
}

// A file whose latent_dims attribute disagrees with its parameters.
TEST(LoadVaeEncoder, LatentMismatchIsAUserErrorNamingTheParameter) {
  TemporaryFolder directory;
  const std::filesystem::path path = directory.path() / "encoder.pt";
  torch::jit::Module script =
      ScriptEncoder(*VaeEncoder(VaeEncoderOptions{}), ObservationSettings{});
  script.setattr("latent_dims", 5);
  script.save(path.string());
  const std::string message = UserErrorMessage([&] { LoadVaeEncoder(path); });
  EXPECT_THAT(message, HasSubstr(path.string()));
  EXPECT_THAT(message, HasSubstr("'fc_mu_weight' has shape [12, 12], expected [5, 12]"));
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

// A shallow encoder's parameters do not fit the deep architecture its attribute claims.
TEST(LoadVaeEncoder, ArchitectureMismatchIsAUserErrorNamingTheParameter) {
  TemporaryFolder directory;
  const std::filesystem::path path = directory.path() / "encoder.pt";
  torch::jit::Module script =
      ScriptEncoder(*VaeEncoder(VaeEncoderOptions{}), ObservationSettings{});
  script.setattr("architecture", std::string("deep"));
  script.save(path.string());
  EXPECT_THAT(UserErrorMessage([&] { LoadVaeEncoder(path); }),
              HasSubstr("'convs_0_weight' has shape [1, 1, 45], expected [3, 1, 45]"));
}

TEST(LoadVaeEncoder, NonFiniteWeightsAreAUserErrorNamingTheParameter) {
  TemporaryFolder directory;
  const std::filesystem::path path = directory.path() / "encoder.pt";
  torch::jit::Module script =
      ScriptEncoder(*VaeEncoder(VaeEncoderOptions{}), ObservationSettings{});
  script.attr("fc_mu_weight").toTensor()[0][0] = std::nanf("");
  script.save(path.string());
  EXPECT_THAT(UserErrorMessage([&] { LoadVaeEncoder(path); }),
              HasSubstr("parameter 'fc_mu_weight' holds NaN or infinite values"));
}

// A TorchScript file that is not an encoder export (here a vae.pt) has no usable attributes or
// parameters.
TEST(LoadVaeEncoder, OtherTorchScriptFilesAreUserErrors) {
  TemporaryFolder directory;
  torch::jit::Module bare("__torch__.Bare");
  bare.define("def forward(self, x: Tensor) -> Tensor:\n    return x\n");
  bare.save((directory.path() / "bare.pt").string());
  EXPECT_THAT(UserErrorMessage([&] { LoadVaeEncoder(directory.path() / "bare.pt"); }),
              HasSubstr("has no attribute 'architecture'"));

  ExportVae(ConvVae(VaeOptions{}), ObservationSettings{}, directory.path() / "vae.pt");
  EXPECT_THAT(UserErrorMessage([&] { LoadVaeEncoder(directory.path() / "vae.pt"); }),
              HasSubstr("has no parameter 'convs_0_weight'"));
}

// Runs `command` through the shell; returns its exit status and its standard output.
std::pair<int, std::string> RunShell(const std::string& command) {
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return {-1, output};
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  return {pclose(pipe), output};
}

// The exported files are the contract with Python tooling: PyTorch's own torch.jit.load must read
// them. python3-torch is a declared test dependency, so its absence fails the test.
TEST(ExportedFiles, LoadInPythonTorch) {
  constexpr char kPython[] = "/usr/bin/python3";
  TemporaryFolder directory;
  torch::manual_seed(13);
  ConvVae vae(VaeOptions{VaeArchitecture::kDeep, 12, DecoderPadding::kCircular});
  ExportEncoder(vae->encoder(), ObservationSettings{}, directory.path() / "encoder.pt");
  ExportVae(vae, ObservationSettings{}, directory.path() / "vae.pt");

  const std::filesystem::path script = directory.path() / "check.py";
  std::ofstream(script) << R"(import sys, torch
encoder = torch.jit.load(sys.argv[1])
vae = torch.jit.load(sys.argv[2])
x = torch.arange(2 * 180, dtype=torch.float32).reshape(2, 180) / 360
mu = encoder(x)
reconstruction, vae_mu, logvar = vae(x)
assert encoder.architecture == "deep" and encoder.latent_dims == 12
assert reconstruction.shape == (2, 180) and logvar.shape == (2, 12)
assert torch.equal(mu, vae_mu)
print("mu:", " ".join(repr(v) for v in mu.flatten().tolist()))
)";
  const auto [status, output] = RunShell(std::string(kPython) + " " + script.string() + " " +
                                         (directory.path() / "encoder.pt").string() + " " +
                                         (directory.path() / "vae.pt").string() + " 2>&1");
  ASSERT_EQ(status, 0) << kPython << " failed to check the exported files; if it cannot import "
                       << "torch, install python3-torch (a test dependency):\n"
                       << output;

  // Whatever Python printed to stderr (warnings) comes before the values.
  const std::size_t values_start = output.rfind("mu:");
  ASSERT_NE(values_start, std::string::npos) << output;
  std::istringstream values(output.substr(values_start + 3));
  std::vector<float> python_mu;
  for (double value; values >> value;) python_mu.push_back(static_cast<float>(value));
  torch::NoGradGuard no_grad;
  const torch::Tensor x = torch::arange(2 * 180, torch::kFloat32).view({2, 180}) / 360;
  const torch::Tensor mu = vae->encoder()->Mu(x).flatten();
  ASSERT_EQ(python_mu.size(), static_cast<std::size_t>(mu.numel())) << output;
  for (std::size_t i = 0; i < python_mu.size(); ++i) {
    EXPECT_NEAR(python_mu[i], mu[i].item<float>(), 1e-6) << "mu[" << i << "]";
  }
}

}  // namespace
}  // namespace colav

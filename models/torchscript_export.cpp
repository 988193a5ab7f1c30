#include "models/torchscript_export.h"

#include <sstream>
#include <vector>

#include "models/cptc.h"
#include "models/observation_settings_record.h"
#include "models/torchscript_source.h"
#include "models/vae_architecture.h"
#include "src/error.h"

namespace colav {
namespace {

constexpr char kArchitectureAttribute[] = "architecture";
constexpr char kLatentDimsAttribute[] = "latent_dims";
constexpr char kDecoderPaddingAttribute[] = "decoder_padding";

std::string DecoderPaddingName(DecoderPadding padding) {
  return padding == DecoderPadding::kCircular ? "circular" : "zero";
}

// Statements taking x [B, 180] to the flattened conv features h [B, 12], each circular Conv1d as
// a wrap followed by an unpadded conv1d; `prefix` is the encoder module's name with its dot ("" or
// "encoder.").
std::string EncoderFeaturesSource(VaeArchitecture architecture, const std::string& prefix) {
  const std::vector<ConvLayerSpec> layers = EncoderConvLayers(architecture);
  std::ostringstream source;
  source << "    h = x.unsqueeze(1)\n";
  for (std::size_t i = 0; i < layers.size(); ++i) {
    source << CircularConv1dSource(prefix + "convs." + std::to_string(i), layers[i].padding,
                                   layers[i].stride);
    if (i + 1 < layers.size()) source << "    h = torch.relu(h)\n";
  }
  source << "    h = h.flatten(1)\n";
  return source.str();
}

std::string DecoderSource(const VaeDecoderOptions& options) {
  const std::vector<ConvLayerSpec> layers = DecoderConvLayers(options.architecture);
  std::ostringstream source;
  source << "def decode(self, z: Tensor) -> Tensor:\n"
         << "    h = torch.relu(" << LinearSource("z", "decoder.fc") << ").unsqueeze(1)\n";
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const ConvLayerSpec& layer = layers[i];
    std::int64_t padding = layer.padding;
    // CPTC as the paper's recipe (models/cptc.h): wrap, transposed convolution, crop; the crop is
    // folded into the transposed convolution's own padding.
    if (options.padding == DecoderPadding::kCircular) {
      const std::int64_t wrap_width = CptcWrapWidth(layer.kernel_size, layer.stride, layer.padding);
      source << WrapSource(wrap_width);
      padding += wrap_width * layer.stride;
    }
    source << ConvTranspose1dSource("decoder.deconvs." + std::to_string(i), layer.stride, padding);
    if (i + 1 < layers.size()) source << "    h = torch.relu(h)\n";
  }
  source << "    return torch.sigmoid(h.flatten(1))\n";
  return source.str();
}

std::string EncoderFileName(const std::filesystem::path& path) {
  return "encoder file '" + path.string() + "'";
}

torch::jit::IValue RequireAttribute(const torch::jit::Module& script, const std::string& name,
                                    const std::filesystem::path& path) {
  if (!script.hasattr(name)) {
    throw UserError(EncoderFileName(path) + " has no attribute '" + name + "'");
  }
  return script.attr(name);
}

torch::jit::Module LoadEncoderScript(const std::filesystem::path& path) {
  return LoadScript(path, EncoderFileName(path));
}

}  // namespace

torch::jit::Module ScriptEncoder(const VaeEncoderImpl& encoder,
                                 const ObservationSettings& settings) {
  const VaeEncoderOptions& options = encoder.options();
  torch::jit::Module script("__torch__.colav.VaeEncoder");
  RegisterParameters(encoder, script);
  script.register_attribute(kArchitectureAttribute, c10::StringType::get(),
                            VaeArchitectureName(options.architecture));
  script.register_attribute(kLatentDimsAttribute, c10::IntType::get(), options.latent_dims);
  RecordObservationSettings(script, settings);
  script.define("def forward(self, x: Tensor) -> Tensor:\n" +
                EncoderFeaturesSource(options.architecture, "") + "    return " +
                LinearSource("h", "fc_mu") + "\n");
  return script;
}

torch::jit::Module ScriptVae(const ConvVaeImpl& vae, const ObservationSettings& settings) {
  const VaeOptions& options = vae.options();
  torch::jit::Module script("__torch__.colav.ConvVae");
  RegisterParameters(vae, script);
  script.register_attribute(kArchitectureAttribute, c10::StringType::get(),
                            VaeArchitectureName(options.architecture));
  script.register_attribute(kLatentDimsAttribute, c10::IntType::get(), options.latent_dims);
  script.register_attribute(kDecoderPaddingAttribute, c10::StringType::get(),
                            DecoderPaddingName(options.decoder_padding));
  RecordObservationSettings(script, settings);
  script.define("def encode(self, x: Tensor) -> Tuple[Tensor, Tensor]:\n" +
                EncoderFeaturesSource(options.architecture, "encoder.") + "    return " +
                LinearSource("h", "encoder.fc_mu") + ", " + LinearSource("h", "encoder.fc_logvar") +
                "\n" + DecoderSource(vae.decoder()->options()) +
                "def forward(self, x: Tensor) -> Tuple[Tensor, Tensor, Tensor]:\n"
                "    mu, logvar = self.encode(x)\n"
                "    z = mu + torch.randn_like(mu) * torch.exp(0.5 * logvar)\n"
                "    return self.decode(z), mu, logvar\n");
  return script;
}

void ExportEncoder(const VaeEncoder& encoder, const ObservationSettings& settings,
                   const std::filesystem::path& path) {
  SaveScript(ScriptEncoder(*encoder, settings), path);
}

void ExportVae(const ConvVae& vae, const ObservationSettings& settings,
               const std::filesystem::path& path) {
  SaveScript(ScriptVae(*vae, settings), path);
}

VaeEncoder LoadVaeEncoder(const std::filesystem::path& path) {
  const std::string file = EncoderFileName(path);
  const torch::jit::Module script = LoadEncoderScript(path);

  const torch::jit::IValue architecture = RequireAttribute(script, kArchitectureAttribute, path);
  const torch::jit::IValue latent_dims = RequireAttribute(script, kLatentDimsAttribute, path);
  VaeEncoderOptions options;
  try {
    options.architecture = ParseVaeArchitecture(architecture.toStringRef());
  } catch (const std::exception&) {
    throw UserError(file + ": attribute 'architecture' is not \"shallow\" or \"deep\"");
  }
  if (!latent_dims.isInt() || latent_dims.toInt() <= 0) {
    throw UserError(file + ": attribute 'latent_dims' is not a positive integer");
  }
  options.latent_dims = latent_dims.toInt();

  VaeEncoder encoder(options);
  torch::NoGradGuard no_grad;
  for (auto& parameter : encoder->named_parameters()) {
    parameter.value().copy_(StoredParameter(
        script, ScriptedParameterName(parameter.key()), parameter.value().sizes(), file,
        " for a " + VaeArchitectureName(options.architecture) + " encoder with latent_dims " +
            std::to_string(options.latent_dims)));
  }
  return encoder;
}

std::optional<ObservationSettings> EncoderObservationSettings(const std::filesystem::path& path) {
  return RecordedObservationSettings(LoadEncoderScript(path), EncoderFileName(path));
}

}  // namespace colav

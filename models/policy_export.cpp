#include "models/policy_export.h"

#include <sstream>
#include <string>

#include "env/environment_spec.h"
#include "models/torchscript_export.h"
#include "src/atomic_file.h"
#include "src/error.h"

namespace colav {
namespace {

constexpr char kObservationLayout[] =
    "obs[:, 0:6] = [u, v, r, cte/100, heading_error, look_ahead_heading_error]; "
    "obs[:, 6:186] = closeness 1 - d/150 of rays i = 0..179 at -pi + (i+1)*2 deg";

std::string Self(const std::string& prefix, const std::string& parameter) {
  return "self." + ScriptedParameterName(prefix + "." + parameter);
}

// `input @ W^T + b` for the Linear module registered under `prefix`.
std::string LinearSource(const std::string& input, const std::string& prefix) {
  return "torch.addmm(" + Self(prefix, "bias") + ", " + input + ", " + Self(prefix, "weight") +
         ".t())";
}

std::string FeaturesSource(FeatureExtractorImpl& extractor) {
  std::ostringstream source;
  source << "def features(self, obs: Tensor) -> Tensor:\n"
         << "    h = obs[:, " << kNavigationSize << ":" << kObservationSize << "].unsqueeze(1)\n";
  for (std::size_t i = 0; i < extractor.layers().size(); ++i) {
    const PerceptionLayer& layer = extractor.layers()[i];
    const std::string prefix = "features_extractor.perception." + std::to_string(i);
    if (layer.conv) {
      const auto& options = layer.conv->options;
      const std::int64_t padding = (*c10::get<torch::ExpandingArray<1>>(options.padding()))[0];
      if (padding > 0) {  // circular: wrap `padding` columns from the opposite end
        const std::string p = std::to_string(padding);
        source << "    h = torch.cat([h[:, :, -" << p << ":], h, h[:, :, :" << p << "]], 2)\n";
      }
      source << "    h = torch.conv1d(h, " << Self(prefix, "weight") << ", " << Self(prefix, "bias")
             << ", [" << (*options.stride())[0] << "])\n";
    } else {
      source << "    h = " << LinearSource("h.flatten(1)", prefix) << "\n";
    }
    if (layer.relu) source << "    h = torch.relu(h)\n";
  }
  source << "    return torch.cat([obs[:, 0:" << kNavigationSize << "], h.flatten(1)], 1)\n";
  return source.str();
}

// Statements taking `f` through a Tanh trunk (Sequential of Linear, Tanh) to `h`.
std::string TrunkSource(torch::nn::Sequential& trunk, const std::string& prefix) {
  std::ostringstream source;
  std::string input = "f";
  for (const auto& child : trunk->named_children()) {
    if (!child.value()->as<torch::nn::Linear>()) continue;
    source << "    h = torch.tanh(" << LinearSource(input, prefix + "." + child.key()) << ")\n";
    input = "h";
  }
  return source.str();
}

}  // namespace

torch::jit::Module ScriptPolicy(ActorCriticImpl& model, std::int64_t global_step) {
  torch::jit::Module script("__torch__.colav.PpoPolicy");
  for (const auto& parameter : model.named_parameters()) {
    script.register_parameter(ScriptedParameterName(parameter.key()),
                              parameter.value().detach().clone(), /*is_buffer=*/false);
  }
  const FeatureExtractorOptions& extractor = model.options().extractor;
  script.register_attribute("extractor", c10::StringType::get(), ExtractorKindName(extractor.kind));
  script.register_attribute("locked", c10::BoolType::get(),
                            !model.features_extractor()->trainable());
  script.register_attribute("global_step", c10::IntType::get(), global_step);
  script.register_attribute("observation_layout", c10::StringType::get(),
                            std::string(kObservationLayout));
  script.define(FeaturesSource(*model.features_extractor()) +
                "def forward(self, obs: Tensor) -> Tensor:\n"
                "    f = self.features(obs)\n" +
                TrunkSource(model.mlp_extractor()->policy_net, "mlp_extractor.policy_net") +
                "    return torch.clamp(" + LinearSource("h", "action_net") + ", -1.0, 1.0)\n" +
                "def value(self, obs: Tensor) -> Tensor:\n"
                "    f = self.features(obs)\n" +
                TrunkSource(model.mlp_extractor()->value_net, "mlp_extractor.value_net") +
                "    return " + LinearSource("h", "value_net") + "\n");
  return script;
}

void ExportPolicy(ActorCriticImpl& model, std::int64_t global_step,
                  const std::filesystem::path& path) {
  const torch::jit::Module script = ScriptPolicy(model, global_step);
  WriteFileAtomically(path, [&](const std::filesystem::path& temporary_path) {
    try {
      script.save(temporary_path.string());
    } catch (const c10::Error&) {
      throw UserError("cannot write TorchScript file '" + path.string() + "'");
    }
  });
}

}  // namespace colav

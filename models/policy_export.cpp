#include "models/policy_export.h"

#include <sstream>
#include <string>

#include "env/environment_spec.h"
#include "models/observation_settings_record.h"
#include "models/torchscript_source.h"

namespace colav {
namespace {

std::string FeaturesSource(FeatureExtractorImpl& extractor, bool normalized_navigation) {
  const std::int64_t scans = extractor.options().scans;
  std::string closeness = "obs[:, " + std::to_string(kNavigationSize) + ":" +
                          std::to_string(extractor.observation_size()) + "]";
  std::string encodings = "h.flatten(1)";
  if (scans > 1) {
    // The scans go through the perception stack as one batch of B * scans single scans (scan k of
    // sample b at row b * scans + k), so their encodings are rows of [B, scans * P].
    closeness +=
        ".reshape(obs.size(0) * " + std::to_string(scans) + ", " + std::to_string(kNumRays) + ")";
    encodings =
        "h.reshape(obs.size(0), " + std::to_string(scans * extractor.perception_dims()) + ")";
  }
  // A policy given observations of another width (another scan history) must not read part of
  // them silently.
  const std::string width = std::to_string(extractor.observation_size());
  std::ostringstream source;
  source << "def features(self, obs: Tensor) -> Tensor:\n"
         << "    assert obs.dim() == 2 and obs.size(1) == " << width
         << ", 'policy: observations [B, " << width << "] expected: " << kNavigationSize
         << " navigation values, then " << scans << " scan(s) of " << kNumRays
         << " closeness values (observation_settings)'\n"
         << "    h = " << closeness << ".unsqueeze(1)\n";
  for (std::size_t i = 0; i < extractor.layers().size(); ++i) {
    const PerceptionLayer& layer = extractor.layers()[i];
    const std::string prefix = "features_extractor.perception." + std::to_string(i);
    if (layer.conv) {
      const auto& options = layer.conv->options;
      source << CircularConv1dSource(prefix,
                                     (*c10::get<torch::ExpandingArray<1>>(options.padding()))[0],
                                     (*options.stride())[0]);
    } else {
      source << "    h = " << LinearSource("h.flatten(1)", prefix) << "\n";
    }
    if (layer.relu) source << "    h = torch.relu(h)\n";
  }
  const std::string navigation = "obs[:, 0:" + std::to_string(kNavigationSize) + "]";
  source << "    return torch.cat(["
         << (normalized_navigation
                 ? "(" + navigation + " - self.navigation_mean) / self.navigation_spread"
                 : navigation)
         << ", " << encodings << "], 1)\n";
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

// A std this small makes expected_clipped_action the clipped mean to the float (a zero std would
// divide 0 by 0 at a mean of exactly +-1).
constexpr double kSmallestDeterministicStd = 1e-30;

// The buffer deterministic_std [2]: the trained std times deterministic_std_scale.
torch::Tensor DeterministicStd(ActorCriticImpl& model) {
  const auto& scale = model.options().deterministic_std_scale;
  const torch::Tensor scales = torch::tensor({scale[0], scale[1]}, torch::kFloat64);
  return (model.log_std().detach().to(torch::kFloat64).exp() * scales)
      .clamp_min(kSmallestDeterministicStd)
      .to(torch::kFloat32);
}

// E[clip(u, -1, 1)] for u ~ N(mean, s^2), with a = (-1 - mean) / s and b = (1 - mean) / s:
// -Phi(a) + (1 - Phi(b)) + mean * (Phi(b) - Phi(a)) + s * (phi(a) - phi(b)).
constexpr const char* kExpectedClippedActionSource =
    "def expected_clipped_action(self, mean: Tensor) -> Tensor:\n"
    "    s = self.deterministic_std\n"
    "    a = (-1.0 - mean) / s\n"
    "    b = (1.0 - mean) / s\n"
    "    cdf_a = 0.5 * (1.0 + torch.erf(a * 0.7071067811865476))\n"
    "    cdf_b = 0.5 * (1.0 + torch.erf(b * 0.7071067811865476))\n"
    "    pdf_a = 0.3989422804014327 * torch.exp(-0.5 * a * a)\n"
    "    pdf_b = 0.3989422804014327 * torch.exp(-0.5 * b * b)\n"
    "    return (1.0 - cdf_b) - cdf_a + mean * (cdf_b - cdf_a) + s * (pdf_a - pdf_b)\n";

// The deterministic action from the Gaussian's `mean`: BoundedAction of models/actor_critic.h, or
// the expected clipped action (ActorCriticOptions::deterministic_std_scale).
std::string DeterministicActionSource(const std::string& mean, const ActorCriticImpl& model) {
  if (model.options().squash_actions) return "torch.tanh(" + mean + ")";
  if (model.options().smooths_deterministic_action()) {
    return "self.expected_clipped_action(" + mean + ")";
  }
  return "torch.clamp(" + mean + ", -1.0, 1.0)";
}

// Statements from the trunk input `f` to the return of the deterministic action, or of the value.
std::string ActionReturnSource(ActorCriticImpl& model, const std::string& rest) {
  return TrunkSource(model.mlp_extractor()->policy_net, "mlp_extractor.policy_net") +
         "    return " + DeterministicActionSource(LinearSource("h", "action_net"), model) + rest +
         "\n";
}
std::string ValueReturnSource(ActorCriticImpl& model, const std::string& rest) {
  return TrunkSource(model.mlp_extractor()->value_net, "mlp_extractor.value_net") + "    return " +
         LinearSource("h", "value_net") + rest + "\n";
}

// A privileged critic's value needs what only training computes: such a file has no value(obs).
std::string MemorylessSource(ActorCriticImpl& model) {
  std::string source =
      "def forward(self, obs: Tensor) -> Tensor:\n"
      "    f = self.features(obs)\n" +
      ActionReturnSource(model, "");
  if (model.options().critic_vessels > 0) return source;
  return source +
         "def value(self, obs: Tensor) -> Tensor:\n"
         "    f = self.features(obs)\n" +
         ValueReturnSource(model, "");
}

// torch.nn.GRUCell (gates r, z, n) of the parameters `cell`_*, written out so that the file needs
// no module of its own; the method is `cell`_cell.
std::string RecurrentCellSource(std::int64_t size, const std::string& cell) {
  const std::string h = std::to_string(size);
  return "def " + cell +
         "_cell(self, x: Tensor, state: Tensor) -> Tensor:\n"
         "    assert state.dim() == 2 and state.size(0) == x.size(0) and state.size(1) == " +
         h + ", 'policy: states [B, " + h +
         "] expected, one row per observation (initial_state(B) at an episode start)'\n"
         "    gi = torch.addmm(self." +
         cell + "_bias_ih, x, self." + cell +
         "_weight_ih.t())\n"
         "    gh = torch.addmm(self." +
         cell + "_bias_hh, state, self." + cell +
         "_weight_hh.t())\n"
         "    i_r, i_z, i_n = gi.chunk(3, 1)\n"
         "    h_r, h_z, h_n = gh.chunk(3, 1)\n"
         "    r = torch.sigmoid(i_r + h_r)\n"
         "    z = torch.sigmoid(i_z + h_z)\n"
         "    n = torch.tanh(i_n + r * h_n)\n"
         "    return (1 - z) * n + z * state\n";
}

// step and step_value: the GRU's next state `s`, then the trunks on [features, s]; step_value
// steps the critic's own GRU when it has one. A privileged critic's policy has no step_value.
std::string RecurrentSource(ActorCriticImpl& model) {
  const std::int64_t H = model.options().recurrent_size;
  const std::string size = std::to_string(H);
  const auto next_state = [](const std::string& cell) {
    return "    x = self.features(obs)\n"
           "    s = self." +
           cell +
           "_cell(x, state)\n"
           "    f = torch.cat([x, s], 1)\n";
  };
  const bool critic_memory = static_cast<bool>(model.critic_recurrent());
  const std::string value_cell = critic_memory ? "critic_recurrent" : "recurrent";
  return RecurrentCellSource(H, "recurrent") +
         (critic_memory ? RecurrentCellSource(H, "critic_recurrent") : std::string()) +
         // The parameters' float32 (torch.float32 does not compile outside Python).
         "def initial_state(self, batch: int) -> Tensor:\n"
         "    return self.recurrent_bias_hh.new_zeros([batch, " +
         size +
         "])\n"
         "def step(self, obs: Tensor, state: Tensor) -> Tuple[Tensor, Tensor]:\n" +
         next_state("recurrent") + ActionReturnSource(model, ", s") +
         (model.options().critic_vessels > 0
              ? std::string()
              : "def step_value(self, obs: Tensor, state: Tensor) -> Tuple[Tensor, Tensor]:\n" +
                    next_state(value_cell) + ValueReturnSource(model, ", s")) +
         // Acting from a zero state at every call would look like a policy and be a worse one.
         // (An assert: builtin exceptions such as RuntimeError only compile from Python.)
         "def forward(self, obs: Tensor) -> Tensor:\n"
         "    assert False, 'recurrent policy: call step(obs, state) starting from "
         "initial_state(B)'\n";
}

// A float32 tensor [kNavigationSize] of `values`.
torch::Tensor NavigationTensor(const std::array<float, kNavigationSize>& values) {
  return torch::tensor(at::ArrayRef<float>(values), torch::kFloat32);
}

}  // namespace

torch::jit::Module ScriptPolicy(ActorCriticImpl& model, std::int64_t global_step,
                                const ObservationSettings& settings,
                                const std::optional<NavigationNormalization>& navigation) {
  torch::jit::Module script("__torch__.colav.PpoPolicy");
  RegisterParameters(model, script);
  if (navigation) {
    script.register_buffer("navigation_mean", NavigationTensor(navigation->mean));
    script.register_buffer("navigation_spread", NavigationTensor(navigation->spread));
  }
  const FeatureExtractorOptions& extractor = model.options().extractor;
  script.register_attribute("extractor", c10::StringType::get(), ExtractorKindName(extractor.kind));
  script.register_attribute("locked", c10::BoolType::get(),
                            !model.features_extractor()->trainable());
  script.register_attribute("scans", c10::IntType::get(), extractor.scans);
  script.register_attribute("global_step", c10::IntType::get(), global_step);
  script.register_attribute("observation_layout", c10::StringType::get(),
                            ObservationLayoutText(settings));
  RecordObservationSettings(script, settings);
  if (model.options().recurrent_size > 0) {
    script.register_attribute("recurrent_size", c10::IntType::get(),
                              model.options().recurrent_size);
  }
  std::string expected_clipped_action;
  if (model.options().smooths_deterministic_action()) {
    script.register_buffer("deterministic_std", DeterministicStd(model));
    expected_clipped_action = kExpectedClippedActionSource;
  }
  script.define(
      FeaturesSource(*model.features_extractor(), navigation.has_value()) +
      expected_clipped_action +
      (model.options().recurrent_size > 0 ? RecurrentSource(model) : MemorylessSource(model)));
  return script;
}

void ExportPolicy(ActorCriticImpl& model, std::int64_t global_step,
                  const ObservationSettings& settings, const std::filesystem::path& path,
                  const std::optional<NavigationNormalization>& navigation) {
  SaveScript(ScriptPolicy(model, global_step, settings, navigation), path);
}

}  // namespace colav

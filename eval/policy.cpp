#include "eval/policy.h"

#include <sstream>
#include <vector>

#include "env/environment_spec.h"
#include "models/observation_settings_record.h"
#include "src/error.h"

namespace colav {
namespace {

// LibTorch messages span many lines (TorchScript tracebacks, C++ frames); the line that says what
// went wrong is the interpreter's "...Error: ..." line when there is one, else the first line.
std::string OneLineReason(const std::exception& error) {
  const auto* torch_error = dynamic_cast<const c10::Error*>(&error);
  std::istringstream lines(torch_error != nullptr ? torch_error->what_without_backtrace()
                                                  : error.what());
  std::string line;
  std::string first;
  std::string reason;
  while (std::getline(lines, line)) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (first.empty()) first = line;
    if (line.rfind("RuntimeError: ", 0) == 0 || line.rfind("Exception: ", 0) == 0) reason = line;
  }
  return reason.empty() ? first : reason;
}

std::string ShapeText(const torch::Tensor& tensor) {
  std::ostringstream text;
  text << tensor.sizes();
  return text.str();
}

}  // namespace

Policy::Policy(const std::filesystem::path& path, std::string name)
    : path_(path), name_(std::move(name)) {
  if (!std::filesystem::is_regular_file(path)) {
    throw UserError(path.string() + ": no such policy file");
  }
  try {
    module_ = torch::jit::load(path.string(), torch::kCPU);
  } catch (const std::exception& error) {
    throw UserError(path.string() + ": not a TorchScript policy (" + OneLineReason(error) + ")");
  }
  if (!module_.find_method("forward")) {
    throw UserError(path.string() + ": TorchScript module has no forward method");
  }
  module_.eval();
  ReadOwnSettings();
  // Probe with two batch sizes: evaluation runs many episodes through one forward call.
  const int observation_size = ObservationSize(SettingsOr(ObservationSettings{}));
  for (const std::int64_t batch : {1, 2}) {
    const torch::Tensor actions = Forward(torch::zeros({batch, observation_size}));
    if (actions.dim() != 2 || actions.size(0) != batch || actions.size(1) != kActionSize) {
      throw UserError(path.string() + ": forward(obs [" + std::to_string(batch) + ", " +
                      std::to_string(observation_size) + "]) gave actions of shape " +
                      ShapeText(actions) + ", expected [" + std::to_string(batch) + ", " +
                      std::to_string(kActionSize) + "]");
    }
  }
}

void Policy::ReadOwnSettings() {
  own_settings_ = RecordedObservationSettings(module_, path_.string());
  if (own_settings_) {
    settings_origin_ = "recorded in the file";
    return;
  }
  const std::filesystem::path sidecar = SidecarPath(path_);
  if (std::filesystem::exists(sidecar)) {
    own_settings_ = LoadObservationSettingsFile(sidecar);
    settings_origin_ = "sidecar " + sidecar.string();
  }
}

torch::Tensor Policy::Forward(const torch::Tensor& observations) {
  torch::IValue output;
  try {
    c10::InferenceMode inference;
    output = module_.forward({observations});
  } catch (const std::exception& error) {
    throw UserError(path_.string() + ": forward(obs " + ShapeText(observations) +
                    ") failed: " + OneLineReason(error));
  }
  if (!output.isTensor()) {
    throw UserError(path_.string() + ": forward must return one tensor of actions, got " +
                    output.tagKind());
  }
  torch::Tensor actions = output.toTensor().to(torch::kFloat32);
  if (!torch::isfinite(actions).all().item<bool>()) {
    throw UserError(path_.string() + ": forward gave a non-finite action");
  }
  return actions;
}

torch::Tensor Policy::Act(const torch::Tensor& observations) {
  return Forward(observations).clamp(-1.0, 1.0);
}

std::filesystem::path SidecarPath(const std::filesystem::path& policy) {
  return policy.string() + ".yaml";
}

std::string DefaultPolicyName(const std::filesystem::path& path) {
  const std::filesystem::path folder = path.parent_path().filename();
  if (path.filename() == "policy.pt" && !folder.empty() && folder != "." && folder != "..") {
    return folder.string();
  }
  return path.stem().string();
}

}  // namespace colav

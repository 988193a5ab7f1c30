#include "eval/policy.h"

#include <functional>
#include <optional>
#include <sstream>
#include <utility>
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

// The two tensors, as float32, of `output` when it is a tuple of two tensors.
std::optional<std::pair<torch::Tensor, torch::Tensor>> FloatTensorPair(
    const torch::IValue& output) {
  if (!output.isTuple()) return std::nullopt;
  const auto& elements = output.toTupleRef().elements();
  if (elements.size() != 2 || !elements[0].isTensor() || !elements[1].isTensor()) {
    return std::nullopt;
  }
  return std::pair{elements[0].toTensor().to(torch::kFloat32),
                   elements[1].toTensor().to(torch::kFloat32)};
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
  ReadRecurrentSize();
  if (!recurrent() && !module_.find_method("forward")) {
    throw UserError(path.string() + ": TorchScript module has no forward method");
  }
  module_.eval();
  ReadOwnSettings();
  // Probe with two batch sizes: evaluation runs many episodes through one call.
  const int observation_size = ObservationSize(SettingsOr(ObservationSettings{}));
  for (const std::int64_t batch : {1, 2}) Probe(batch, observation_size);
}

void Policy::ReadRecurrentSize() {
  if (!module_.hasattr("recurrent_size")) return;
  const torch::IValue size = module_.attr("recurrent_size");
  if (!size.isInt() || size.toInt() < 0) {
    throw UserError(path_.string() + ": attribute recurrent_size must be an int >= 0");
  }
  recurrent_size_ = static_cast<int>(size.toInt());
  if (!recurrent()) return;
  for (const char* method : {"initial_state", "step"}) {
    if (!module_.find_method(method)) {
      throw UserError(path_.string() + ": recurrent policy (recurrent_size " +
                      std::to_string(recurrent_size_) + ") has no " + method + " method");
    }
  }
}

void Policy::Probe(std::int64_t batch, int observation_size) {
  const torch::Tensor observations = torch::zeros({batch, observation_size});
  const std::string call = "(obs " + ShapeText(observations);
  if (!recurrent()) {
    ExpectShape(Forward(observations), batch, kActionSize, "forward" + call + ") gave actions");
    return;
  }
  torch::Tensor states = InitialStates(batch);
  ExpectShape(states, batch, recurrent_size_,
              "initial_state(" + std::to_string(batch) + ") gave states");
  const torch::Tensor actions = Step(observations, states);
  ExpectShape(actions, batch, kActionSize, "step" + call + ", state) gave actions");
  ExpectShape(states, batch, recurrent_size_, "step" + call + ", state) gave next states");
}

void Policy::ExpectShape(const torch::Tensor& tensor, std::int64_t rows, std::int64_t columns,
                         const std::string& what) const {
  if (tensor.dim() != 2 || tensor.size(0) != rows || tensor.size(1) != columns) {
    throw UserError(path_.string() + ": " + what + " of shape " + ShapeText(tensor) +
                    ", expected [" + std::to_string(rows) + ", " + std::to_string(columns) + "]");
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

torch::IValue Policy::Run(const std::string& method, std::vector<torch::IValue> inputs,
                          const std::function<std::string()>& describe_call) {
  try {
    c10::InferenceMode inference;
    return module_.get_method(method)(std::move(inputs));
  } catch (const std::exception& error) {
    throw UserError(path_.string() + ": " + describe_call() + " failed: " + OneLineReason(error));
  }
}

torch::Tensor Policy::Forward(const torch::Tensor& observations) {
  const torch::IValue output = Run("forward", {observations},
                                   [&] { return "forward(obs " + ShapeText(observations) + ")"; });
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
  TORCH_CHECK(!recurrent(), path_.string(), ": a recurrent policy acts through Step");
  return Forward(observations).clamp(-1.0, 1.0);
}

torch::Tensor Policy::Step(const torch::Tensor& observations, torch::Tensor& states) {
  TORCH_CHECK(recurrent(), path_.string(), ": a memoryless policy acts through Act");
  const torch::IValue output = Run("step", {observations, states}, [&] {
    return "step(obs " + ShapeText(observations) + ", state " + ShapeText(states) + ")";
  });
  const std::optional<std::pair<torch::Tensor, torch::Tensor>> pair = FloatTensorPair(output);
  if (!pair) {
    throw UserError(path_.string() + ": step must return a tuple (actions, next states), got " +
                    output.tagKind());
  }
  const auto& [actions, next_states] = *pair;
  if (!torch::isfinite(actions).all().item<bool>() ||
      !torch::isfinite(next_states).all().item<bool>()) {
    throw UserError(path_.string() + ": step gave a non-finite action or state");
  }
  states = next_states;
  return actions.clamp(-1.0, 1.0);
}

torch::Tensor Policy::InitialStates(std::int64_t batch) {
  TORCH_CHECK(recurrent(), path_.string(), ": a memoryless policy has no state");
  const torch::IValue output =
      Run("initial_state", {batch}, [&] { return "initial_state(" + std::to_string(batch) + ")"; });
  if (!output.isTensor()) {
    throw UserError(path_.string() + ": initial_state must return one tensor, got " +
                    output.tagKind());
  }
  // A normal tensor, not an inference one: callers write next states into it in place.
  return output.toTensor().to(torch::kFloat32).clone();
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

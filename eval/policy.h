// A trained agent as the evaluation sees it: a TorchScript policy file (spec interfaces.md,
// policy.pt: forward(obs float32 [B, 186 + 180 * scan_history]) -> deterministic action [B, 2]
// in [-1, 1]; a recurrent policy, with the attribute recurrent_size H > 0, instead has
// initial_state(B) -> state [B, H] and step(obs, state) -> (action, next state),
// models/policy_export.h) and the observation settings it was trained with: recorded in the file
// (models/observation_settings_record.h), else in a sidecar file "<policy file>.yaml" beside it
// (spec interfaces.md, "Observation settings travel with models").
#pragma once

#include <torch/script.h>
#include <torch/torch.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "env/observation_settings.h"

namespace colav {

class Policy {
 public:
  /// Loads and checks `path`: it must exist, be TorchScript with a forward method, and map
  /// observations [1, n] and [2, n] (n = ObservationSize of its settings, 186 without them) to
  /// finite actions [1, 2] and [2, 2]. A recurrent file needs initial_state and step instead of
  /// forward, and step from initial_state(B) must give actions [B, 2] and next states [B, H] for
  /// B = 1, 2. Anything else is a one-line UserError naming the file; so is a malformed settings
  /// record or sidecar.
  Policy(const std::filesystem::path& path, std::string name);

  /// Deterministic actions [B, 2] for observations [B, n], clipped to [-1, 1]. A failing
  /// forward or a non-finite action is a UserError naming the file. Memoryless policies only.
  torch::Tensor Act(const torch::Tensor& observations);

  /// Recurrent policies: deterministic actions [B, 2], clipped to [-1, 1], for observations
  /// [B, n] given `states` [B, H] (InitialStates at an episode's start), which become the states
  /// after these observations. A failing step or a non-finite output is a UserError naming the
  /// file.
  torch::Tensor Step(const torch::Tensor& observations, torch::Tensor& states);
  /// The file's initial_state(batch): the states [batch, H] of episodes about to start.
  torch::Tensor InitialStates(std::int64_t batch);

  bool recurrent() const { return recurrent_size_ > 0; }
  /// H, the size of a recurrent policy's state; 0 for a memoryless one.
  int recurrent_size() const { return recurrent_size_; }

  const std::string& name() const { return name_; }
  const std::filesystem::path& path() const { return path_; }
  /// The loaded TorchScript module (eval/policy_ensemble.h makes it a submodule).
  const torch::jit::Module& module() const { return module_; }
  /// The observation settings the policy was trained with, when its file or sidecar says.
  const std::optional<ObservationSettings>& own_settings() const { return own_settings_; }
  /// Where own_settings() come from: "recorded in the file", "sidecar <file>", or "unknown".
  const std::string& settings_origin() const { return settings_origin_; }
  /// The settings to run the policy under: its own, else `fallback` (the evaluation's).
  ObservationSettings SettingsOr(const ObservationSettings& fallback) const {
    return own_settings_.value_or(fallback);
  }

 private:
  torch::Tensor Forward(const torch::Tensor& observations);
  /// Runs `method`; a failure is a UserError naming the file and describe_call()'s text, which is
  /// built only then (the evaluation calls a policy at every step).
  torch::IValue Run(const std::string& method, std::vector<torch::IValue> inputs,
                    const std::function<std::string()>& describe_call);
  void ReadRecurrentSize();
  void Probe(std::int64_t batch, int observation_size);
  void ExpectShape(const torch::Tensor& tensor, std::int64_t rows, std::int64_t columns,
                   const std::string& what) const;
  void ReadOwnSettings();

  std::filesystem::path path_;
  std::string name_;
  torch::jit::Module module_;
  std::optional<ObservationSettings> own_settings_;
  std::string settings_origin_ = "unknown";
  int recurrent_size_ = 0;
};

/// The sidecar file of a policy file: "<policy file>.yaml".
std::filesystem::path SidecarPath(const std::filesystem::path& policy);

/// The default model name of a policy file: its folder's name for ".../RUN/policy.pt" (train_ppo
/// run folders), else the file name without extension.
std::string DefaultPolicyName(const std::filesystem::path& path);

}  // namespace colav

// A trained agent as the evaluation sees it: a TorchScript policy file (spec interfaces.md,
// policy.pt: forward(obs float32 [B, 186]) -> deterministic action [B, 2] in [-1, 1]).
#pragma once

#include <torch/script.h>
#include <torch/torch.h>

#include <filesystem>
#include <string>

namespace colav {

class Policy {
 public:
  /// Loads and checks `path`: it must exist, be TorchScript with a forward method, and map
  /// observations [1, 186] and [2, 186] to finite actions [1, 2] and [2, 2]. Anything else is a
  /// one-line UserError naming the file.
  Policy(const std::filesystem::path& path, std::string name);

  /// Deterministic actions [B, 2] for observations [B, 186], clipped to [-1, 1]. A failing
  /// forward or a non-finite action is a UserError naming the file.
  torch::Tensor Act(const torch::Tensor& observations);

  const std::string& name() const { return name_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  torch::Tensor Forward(const torch::Tensor& observations);

  std::filesystem::path path_;
  std::string name_;
  torch::jit::Module module_;
};

/// The default model name of a policy file: its folder's name for ".../RUN/policy.pt" (train_ppo
/// run folders), else the file name without extension.
std::string DefaultPolicyName(const std::filesystem::path& path);

}  // namespace colav

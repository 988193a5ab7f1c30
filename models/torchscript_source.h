// The building blocks of the TorchScript exports (models/torchscript_export.h for the VAE,
// models/policy_export.h for the policy) and of reading their weights back: the C++ module's
// parameters copied into a torch::jit::Module and out of one, and TorchScript source statements
// that use them. A parameter `a.b.c` of the C++ module is the attribute `a_b_c` of the scripted
// one. Statements work on the variable `h`.
#pragma once

#include <torch/script.h>
#include <torch/torch.h>

#include <cstdint>
#include <filesystem>
#include <string>

namespace colav {

/// The scripted name of a C++ parameter name: "fc_mu.weight" -> "fc_mu_weight".
std::string ScriptedParameterName(const std::string& name);

/// `input @ W^T + b` for the Linear module registered as `module` ("fc_mu",
/// "features_extractor.perception.2").
std::string LinearSource(const std::string& input, const std::string& module);
/// Statements that wrap the length axis of `h` by `width` columns from the opposite end (none for
/// width 0).
std::string WrapSource(std::int64_t width);
/// Statements for the Conv1d `module` with circular padding `padding`: a wrap, then an unpadded
/// conv1d.
std::string CircularConv1dSource(const std::string& module, std::int64_t padding,
                                 std::int64_t stride);
/// The statement for the ConvTranspose1d `module`.
std::string ConvTranspose1dSource(const std::string& module, std::int64_t stride,
                                  std::int64_t padding);

/// Copies every parameter of `module` into `script` as a float32 CPU tensor.
void RegisterParameters(const torch::nn::Module& module, torch::jit::Module& script);
/// The TorchScript file at `path`; a missing or unreadable one is a UserError naming `file` (a
/// description of the file and its path, "encoder file 'x.pt'").
torch::jit::Module LoadScript(const std::filesystem::path& path, const std::string& file);
/// The parameter `name` (a scripted name) of `script`, which must be a tensor of
/// `expected_shape` holding finite values; else a UserError naming `file` and `name`, and for a
/// wrong shape both shapes followed by `shape_context` (" for a shallow encoder", say).
torch::Tensor StoredParameter(const torch::jit::Module& script, const std::string& name,
                              at::IntArrayRef expected_shape, const std::string& file,
                              const std::string& shape_context);
/// Writes `script` to `path` through WriteFileAtomically (parent folders created, no
/// half-written file on failure). A path that cannot be written is a UserError naming it.
void SaveScript(const torch::jit::Module& script, const std::filesystem::path& path);

}  // namespace colav

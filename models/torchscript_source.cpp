#include "models/torchscript_source.h"

#include <sstream>

#include "src/atomic_file.h"
#include "src/error.h"

namespace colav {
namespace {

std::string ParameterSource(const std::string& module, const std::string& parameter) {
  return "self." + ScriptedParameterName(module + "." + parameter);
}

}  // namespace

std::string ScriptedParameterName(const std::string& name) {
  std::string scripted = name;
  for (char& c : scripted) {
    if (c == '.') c = '_';
  }
  return scripted;
}

std::string LinearSource(const std::string& input, const std::string& module) {
  return "torch.addmm(" + ParameterSource(module, "bias") + ", " + input + ", " +
         ParameterSource(module, "weight") + ".t())";
}

std::string WrapSource(std::int64_t width) {
  if (width == 0) return "";
  const std::string w = std::to_string(width);
  return "    h = torch.cat([h[:, :, -" + w + ":], h, h[:, :, :" + w + "]], 2)\n";
}

std::string CircularConv1dSource(const std::string& module, std::int64_t padding,
                                 std::int64_t stride) {
  return WrapSource(padding) + "    h = torch.conv1d(h, " + ParameterSource(module, "weight") +
         ", " + ParameterSource(module, "bias") + ", [" + std::to_string(stride) + "])\n";
}

std::string ConvTranspose1dSource(const std::string& module, std::int64_t stride,
                                  std::int64_t padding) {
  return "    h = torch.conv_transpose1d(h, " + ParameterSource(module, "weight") + ", " +
         ParameterSource(module, "bias") + ", [" + std::to_string(stride) + "], [" +
         std::to_string(padding) + "])\n";
}

void RegisterParameters(const torch::nn::Module& module, torch::jit::Module& script) {
  for (const auto& parameter : module.named_parameters()) {
    script.register_parameter(ScriptedParameterName(parameter.key()),
                              parameter.value().detach().to(torch::kCPU, torch::kFloat32,
                                                            /*non_blocking=*/false, /*copy=*/true),
                              /*is_buffer=*/false);
  }
}

torch::jit::Module LoadScript(const std::filesystem::path& path, const std::string& file) {
  if (!std::filesystem::is_regular_file(path)) throw UserError(file + " does not exist");
  try {
    return torch::jit::load(path.string(), torch::kCPU);
  } catch (const std::exception&) {
    throw UserError(file + " is not a TorchScript file");
  }
}

torch::Tensor StoredParameter(const torch::jit::Module& script, const std::string& name,
                              at::IntArrayRef expected_shape, const std::string& file,
                              const std::string& shape_context) {
  if (!script.hasattr(name) || !script.attr(name).isTensor()) {
    throw UserError(file + " has no parameter '" + name + "'");
  }
  torch::Tensor stored = script.attr(name).toTensor();
  if (stored.sizes() != expected_shape) {
    std::ostringstream message;
    message << file << ": parameter '" << name << "' has shape " << stored.sizes() << ", expected "
            << expected_shape << shape_context;
    throw UserError(message.str());
  }
  if (!torch::isfinite(stored).all().item<bool>()) {
    throw UserError(file + ": parameter '" + name + "' holds NaN or infinite values");
  }
  return stored;
}

void SaveScript(const torch::jit::Module& script, const std::filesystem::path& path) {
  WriteFileAtomically(path, [&](const std::filesystem::path& temporary_path) {
    try {
      script.save(temporary_path.string());
    } catch (const c10::Error&) {
      throw UserError("cannot write TorchScript file '" + path.string() + "'");
    }
  });
}

}  // namespace colav

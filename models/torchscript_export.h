// TorchScript export of the VAE, written without Python: the modules' parameters are copied into a
// torch::jit::Module whose methods are defined from TorchScript source generated here, so the
// files load with torch.jit.load in Python and torch::jit::load in C++.
//
// Contract (spec interfaces.md):
//   encoder.pt: forward(x: float32 [B, 180] closeness) -> mu [B, latent]; attributes
//               `architecture` (str, "shallow" | "deep"), `latent_dims` (int) and
//               `observation_settings` (str, the closeness transform of the training scans,
//               models/observation_settings_record.h).
//   vae.pt:     forward(x) -> (reconstruction [B, 180], mu [B, latent], logvar [B, latent]),
//               sampling z = mu + eps * exp(logvar / 2) with eps = torch.randn_like(mu); also
//               encode(x) -> (mu, logvar) and decode(z) -> reconstruction; attributes
//               `architecture`, `latent_dims`, `observation_settings` and `decoder_padding` (str,
//               "circular" | "zero").
// Parameters are named as models/torchscript_source.h says.
#pragma once

#include <torch/script.h>
#include <torch/torch.h>

#include <filesystem>
#include <optional>
#include <string>

#include "env/observation_settings.h"
#include "models/conv_vae.h"
#include "models/vae_encoder.h"

namespace colav {

// The scripted modules, in memory, recording the observation `settings` of their training scans.
// Parameters are float32 copies, detached from the C++ module.
torch::jit::Module ScriptEncoder(const VaeEncoderImpl& encoder,
                                 const ObservationSettings& settings);
torch::jit::Module ScriptVae(const ConvVaeImpl& vae, const ObservationSettings& settings);

// Write the scripted module to `path` (SaveScript, models/torchscript_source.h).
void ExportEncoder(const VaeEncoder& encoder, const ObservationSettings& settings,
                   const std::filesystem::path& path);
void ExportVae(const ConvVae& vae, const ObservationSettings& settings,
               const std::filesystem::path& path);

// Rebuild a VaeEncoder from an encoder.pt written by ExportEncoder. A missing file, a file that is
// not TorchScript, a missing or malformed attribute or parameter, or a parameter whose shape does
// not fit `architecture` and `latent_dims` is a UserError naming the file.
VaeEncoder LoadVaeEncoder(const std::filesystem::path& path);

// The observation settings an encoder file records (none for a file written without them); the
// same errors as LoadVaeEncoder for a file that is not an encoder.
std::optional<ObservationSettings> EncoderObservationSettings(const std::filesystem::path& path);

}  // namespace colav

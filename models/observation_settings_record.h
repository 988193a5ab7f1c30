// Observation settings recorded inside a TorchScript model file (policy.pt, encoder.pt, vae.pt):
// the string attribute `observation_settings` holds env/observation_settings.h's YAML text, so a
// model never meets observations of another meaning without somebody saying so.
#pragma once

#include <torch/script.h>

#include <optional>
#include <string>

#include "env/observation_settings.h"

namespace colav {

/// The name of the attribute.
inline constexpr char kObservationSettingsAttribute[] = "observation_settings";

/// Adds the attribute to `script`.
void RecordObservationSettings(torch::jit::Module& script, const ObservationSettings& settings);

/// The settings `script` records; none for a file written without them (older files, models
/// converted from elsewhere). A malformed record is a UserError naming `file`.
std::optional<ObservationSettings> RecordedObservationSettings(const torch::jit::Module& script,
                                                               const std::string& file);

}  // namespace colav

#include "models/observation_settings_record.h"

#include "src/error.h"

namespace colav {

void RecordObservationSettings(torch::jit::Module& script, const ObservationSettings& settings) {
  script.register_attribute(kObservationSettingsAttribute, c10::StringType::get(),
                            ObservationSettingsYaml(settings));
}

std::optional<ObservationSettings> RecordedObservationSettings(const torch::jit::Module& script,
                                                               const std::string& file) {
  if (!script.hasattr(kObservationSettingsAttribute)) return std::nullopt;
  const torch::jit::IValue value = script.attr(kObservationSettingsAttribute);
  if (!value.isString()) {
    throw UserError(file + ": attribute '" + kObservationSettingsAttribute + "' is not a string");
  }
  return ParseObservationSettingsYaml(value.toStringRef(), file);
}

}  // namespace colav

#include "train/ppo/encoder_check.h"

#include <spdlog/spdlog.h>

#include "env/environment_config.h"
#include "env/observation_settings.h"
#include "models/torchscript_export.h"
#include "src/error.h"

namespace colav {

void CheckEncoderObservationSettings(const PpoRunOptions& options) {
  const FeatureExtractorOptions& extractor = options.model.extractor;
  if (extractor.kind == ExtractorKind::kBaseline) return;
  const std::string file = extractor.encoder.string();
  const std::optional<ObservationSettings> recorded = EncoderObservationSettings(extractor.encoder);
  const ObservationSettings expected{options.encoder_closeness.value_or(options.env.closeness)};
  if (!recorded) {
    spdlog::warn("encoder file '{}' does not record its observation settings; assuming {}", file,
                 DescribeObservationSettings(expected));
    return;
  }
  if (*recorded == expected) {
    if (expected != ObservationSettingsOf(options.env)) {
      spdlog::info("encoder trained on {} fed {} (extractor.encoder_closeness: {})",
                   DescribeObservationSettings(expected),
                   DescribeObservationSettings(ObservationSettingsOf(options.env)),
                   ClosenessTransformName(expected.closeness));
    }
    return;
  }
  throw UserError(
      "encoder file '" + file + "' was trained on " + DescribeObservationSettings(*recorded) +
      ", extractor.encoder_closeness expects " + DescribeObservationSettings(expected) +
      " (env has " + DescribeObservationSettings(ObservationSettingsOf(options.env)) +
      "); set extractor.encoder_closeness=" + ClosenessTransformName(recorded->closeness) +
      " to train on it");
}

}  // namespace colav

#include "train/ppo/encoder_check.h"

#include <spdlog/spdlog.h>

#include "env/observation_settings.h"
#include "models/torchscript_export.h"
#include "src/error.h"

namespace colav {

void CheckEncoderObservationSettings(const PpoRunOptions& options) {
  const FeatureExtractorOptions& extractor = options.model.extractor;
  if (extractor.kind == ExtractorKind::kBaseline) return;
  const std::string file = extractor.encoder.string();
  const std::optional<ObservationSettings> recorded = EncoderObservationSettings(extractor.encoder);
  const ObservationSettings run = ObservationSettingsOf(options.env);
  if (!recorded) {
    spdlog::warn("encoder file '{}' does not record its observation settings; assuming {}", file,
                 DescribeObservationSettings(run));
    return;
  }
  if (*recorded == run) return;
  const std::string mismatch = "encoder file '" + file + "' was trained on " +
                               DescribeObservationSettings(*recorded) + ", env has " +
                               DescribeObservationSettings(run);
  if (!options.allow_encoder_mismatch) {
    throw UserError(mismatch + " (set env.closeness to match, or --allow-encoder-mismatch)");
  }
  spdlog::warn("{}: training anyway (extractor.allow_encoder_mismatch)", mismatch);
}

}  // namespace colav

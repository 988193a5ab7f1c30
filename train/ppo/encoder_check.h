// The pre-trained encoder of a VAE extractor must have been trained on observations that mean what
// the run's environment produces: a locked encoder fed log closeness after training on linear
// closeness sees scans it never saw.
#pragma once

#include "train/ppo/config.h"

namespace colav {

/// For a VAE extractor: an encoder file recording other observation settings than `options.env`
/// is a UserError naming the file, both settings and extractor.allow_encoder_mismatch, unless that
/// key is set; an encoder recording none gets a warning on the log. Nothing for the baseline.
void CheckEncoderObservationSettings(const PpoRunOptions& options);

}  // namespace colav

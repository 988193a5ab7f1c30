// The pre-trained encoder of a VAE extractor must have been trained on the observations the run
// expects it to have seen: a locked encoder fed scans of another transform than the one it was
// trained on sees scans it never saw, so that happens only where the configuration says so
// (extractor.encoder_closeness; the paper recipe's linear-trained encoder in log closeness).
#pragma once

#include "train/ppo/config.h"

namespace colav {

/// For a VAE extractor: an encoder file recording another closeness than
/// `options.encoder_closeness` (or env.closeness where that is empty) is a UserError naming the
/// file, both transforms and extractor.encoder_closeness; an encoder recording none gets a
/// warning on the log. Nothing for the baseline.
void CheckEncoderObservationSettings(const PpoRunOptions& options);

}  // namespace colav

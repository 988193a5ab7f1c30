// generate_dataset's configuration keys (configs/dataset.yaml documents the defaults).
#pragma once

#include "src/config.h"
#include "train/dataset/generation.h"

namespace colav {

ConfigSchema DatasetGenerationSchema();

/// The options of a resolved configuration; inconsistent keys (a minimum above its maximum,
/// shares above 1) are a UserError naming them.
DatasetGenerationOptions DatasetGenerationOptionsFrom(const Config& config);

}  // namespace colav

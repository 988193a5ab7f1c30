// generate_dataset's configuration keys, bound to DatasetGenerationOptions
// (configs/dataset.yaml lists the defaults).
#pragma once

#include "src/options_binding.h"
#include "train/dataset/generation.h"

namespace colav {

/// The dataset.*, augmentation.*, synthetic.*, pilot.* and recording.* keys. Reading inconsistent
/// keys (a minimum above its maximum, shares above 1) is a UserError naming them.
OptionsBinding<DatasetGenerationOptions> DatasetGenerationBinding();

}  // namespace colav

// Raw float pointers into LibTorch tensors, for the hand-written kernels of the fast paths.
#pragma once

#include <torch/torch.h>

namespace colav {

/// The first value of a float32 tensor (data_ptr checks the type; callers pass contiguous ones).
inline float* FloatData(const torch::Tensor& tensor) { return tensor.data_ptr<float>(); }

}  // namespace colav

// CPU kernels shared by the circular Conv1d (encoder) and its transpose CPTC-1D (decoder).
//
// Both layers connect a short signal of length L to a long one of length N = stride * L laid on a
// ring: short position i and kernel tap t meet long position (stride * i + t - padding) mod N. The
// convolution gathers along these links (long -> short), CPTC spreads along them (short -> long),
// and both layers' weight gradients correlate the two signals over them, so three loops cover the
// forward and backward passes of both. They index the ring directly (no padded copies through
// LibTorch ops and no per-sample GEMM as in LibTorch's slow transposed-convolution path), which
// keeps a training step of the small VAEs cheap.
//
// Shapes: long [B, C, N], short [B, O, L], weight [O, C, k] (Conv1d's [out, in, k], and
// ConvTranspose1d's [in, out, k]), bias [O] or [C] or undefined. Tensors are contiguous CPU float
// or double. A layer tiles the ring only when k - 2 * padding == stride, which the callers check.
#pragma once

#include <torch/torch.h>

#include <cstdint>

namespace colav {

// Where the circular layers' autograd functions keep their stride and padding (saved_data).
inline constexpr char kStrideKey[] = "stride";
inline constexpr char kPaddingKey[] = "padding";

// short[b, o, i] = bias[o] + sum_{c, t} weight[o, c, t] long[b, c, (stride i + t - padding) mod N]
torch::Tensor CircularGather(const torch::Tensor& long_signal, const torch::Tensor& weight,
                             const torch::Tensor& bias, std::int64_t stride, std::int64_t padding);

// long[b, c, n] = bias[c] + sum over (o, i, t) linked to n of weight[o, c, t] short[b, o, i]: the
// adjoint of CircularGather.
torch::Tensor CircularSpread(const torch::Tensor& short_signal, const torch::Tensor& weight,
                             const torch::Tensor& bias, std::int64_t stride, std::int64_t padding);

// weight_gradient[o, c, t] = sum_{b, i} short[b, o, i] long[b, c, (stride i + t - padding) mod N]
torch::Tensor CircularWeightGradient(const torch::Tensor& short_signal,
                                     const torch::Tensor& long_signal, std::int64_t kernel_size,
                                     std::int64_t stride, std::int64_t padding);

// Checks the geometry above for a layer with this kernel whose short side has `short_length`
// positions; throws c10::Error naming the mismatch.
void CheckCircularGeometry(std::int64_t kernel_size, std::int64_t stride, std::int64_t padding,
                           std::int64_t short_length);

}  // namespace colav

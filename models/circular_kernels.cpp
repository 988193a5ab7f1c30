#include "models/circular_kernels.h"

#include <algorithm>
#include <vector>

namespace colav {
namespace {

// ring[q] = row[(q - padding) mod N] for q in [0, N + 2 padding): the row with `padding` columns
// wrapped around each end, so window i of the layer starts at ring + stride * i.
template <typename T>
void WrapRow(const T* row, std::int64_t length, std::int64_t padding, T* ring) {
  std::copy(row + length - padding, row + length, ring);
  std::copy(row, row + length, ring + padding);
  std::copy(row, row + padding, ring + padding + length);
}

// The two inner loops of the kernels. They work in blocks of four independent lanes, which the
// compiler turns into SIMD instructions at -O2, and stay out of line: inlined into the kernels
// they ran out of registers and spilled their loop pointer on every iteration (3x slower).
constexpr std::int64_t kLanes = 4;

// sum_t a[t] b[t], accumulated in four interleaved partial sums (a fixed summation order, so
// results are reproducible).
template <typename T>
[[gnu::noinline]] T Dot(const T* __restrict a, const T* __restrict b, std::int64_t size) {
  T sums[kLanes] = {};
  std::int64_t t = 0;
  for (; t + kLanes <= size; t += kLanes) {
    for (std::int64_t lane = 0; lane < kLanes; ++lane) sums[lane] += a[t + lane] * b[t + lane];
  }
  for (; t < size; ++t) sums[0] += a[t] * b[t];
  static_assert(kLanes == 4);
  return (sums[0] + sums[1]) + (sums[2] + sums[3]);
}

// y[t] += alpha x[t]
template <typename T>
[[gnu::noinline]] void Axpy(T alpha, const T* __restrict x, T* __restrict y, std::int64_t size) {
  std::int64_t t = 0;
  for (; t + kLanes <= size; t += kLanes) {
    for (std::int64_t lane = 0; lane < kLanes; ++lane) y[t + lane] += alpha * x[t + lane];
  }
  for (; t < size; ++t) y[t] += alpha * x[t];
}

struct Sizes {
  std::int64_t batch, long_channels, short_channels, long_length, short_length, kernel_size;
};

template <typename T>
void Gather(const T* long_data, const T* weight, const T* bias, T* short_data, const Sizes& n,
            std::int64_t stride, std::int64_t padding) {
  std::vector<T> ring(n.long_length + 2 * padding);
  for (std::int64_t b = 0; b < n.batch; ++b) {
    T* out = short_data + b * n.short_channels * n.short_length;
    for (std::int64_t o = 0; o < n.short_channels; ++o) {
      std::fill_n(out + o * n.short_length, n.short_length, bias ? bias[o] : T{0});
    }
    for (std::int64_t c = 0; c < n.long_channels; ++c) {
      WrapRow(long_data + (b * n.long_channels + c) * n.long_length, n.long_length, padding,
              ring.data());
      for (std::int64_t o = 0; o < n.short_channels; ++o) {
        const T* w = weight + (o * n.long_channels + c) * n.kernel_size;
        T* y = out + o * n.short_length;
        for (std::int64_t i = 0; i < n.short_length; ++i) {
          y[i] += Dot(w, ring.data() + stride * i, n.kernel_size);
        }
      }
    }
  }
}

template <typename T>
void Spread(const T* short_data, const T* weight, const T* bias, T* long_data, const Sizes& n,
            std::int64_t stride, std::int64_t padding) {
  const std::int64_t length = n.long_length;
  std::vector<T> ring(length + 2 * padding);
  for (std::int64_t b = 0; b < n.batch; ++b) {
    for (std::int64_t c = 0; c < n.long_channels; ++c) {
      std::fill(ring.begin(), ring.end(), T{0});
      for (std::int64_t o = 0; o < n.short_channels; ++o) {
        const T* z = short_data + (b * n.short_channels + o) * n.short_length;
        const T* w = weight + (o * n.long_channels + c) * n.kernel_size;
        for (std::int64_t i = 0; i < n.short_length; ++i) {
          Axpy(z[i], w, ring.data() + stride * i, n.kernel_size);
        }
      }
      // Fold the wrapped ends back onto the columns they stand for.
      T* out = long_data + (b * n.long_channels + c) * length;
      const T offset = bias ? bias[c] : T{0};
      for (std::int64_t m = 0; m < length; ++m) out[m] = offset + ring[padding + m];
      for (std::int64_t m = 0; m < padding; ++m) {
        out[m] += ring[padding + length + m];
        out[length - padding + m] += ring[m];
      }
    }
  }
}

template <typename T>
void WeightGradient(const T* short_data, const T* long_data, T* gradient, const Sizes& n,
                    std::int64_t stride, std::int64_t padding) {
  std::vector<T> ring(n.long_length + 2 * padding);
  for (std::int64_t b = 0; b < n.batch; ++b) {
    for (std::int64_t c = 0; c < n.long_channels; ++c) {
      WrapRow(long_data + (b * n.long_channels + c) * n.long_length, n.long_length, padding,
              ring.data());
      for (std::int64_t o = 0; o < n.short_channels; ++o) {
        const T* z = short_data + (b * n.short_channels + o) * n.short_length;
        T* g = gradient + (o * n.long_channels + c) * n.kernel_size;
        for (std::int64_t i = 0; i < n.short_length; ++i) {
          Axpy(z[i], ring.data() + stride * i, g, n.kernel_size);
        }
      }
    }
  }
}

// `channels_dim`: the weight dimension that matches the signal's channels; the bias, if any,
// matches the other one.
void CheckTensors(const torch::Tensor& signal, const torch::Tensor& weight,
                  const torch::Tensor& bias, std::int64_t channels_dim) {
  TORCH_CHECK(signal.dim() == 3, "circular layer expects a [B, C, L] signal, got ", signal.sizes());
  TORCH_CHECK(weight.dim() == 3 && weight.size(channels_dim) == signal.size(1),
              "circular layer weight ", weight.sizes(), " does not fit a signal with ",
              signal.size(1), " channels");
  TORCH_CHECK(signal.is_contiguous() && weight.is_contiguous() && signal.device().is_cpu() &&
                  signal.scalar_type() == weight.scalar_type(),
              "circular layer kernels need contiguous CPU tensors of one dtype");
  TORCH_CHECK(
      !bias.defined() || (bias.dim() == 1 && bias.size(0) == weight.size(1 - channels_dim) &&
                          bias.is_contiguous() && bias.scalar_type() == weight.scalar_type()),
      "circular layer bias ", bias.sizes(), " does not fit weight ", weight.sizes());
}

template <typename T>
const T* DataOrNull(const torch::Tensor& tensor) {
  return tensor.defined() ? tensor.data_ptr<T>() : nullptr;
}

}  // namespace

void CheckCircularGeometry(std::int64_t kernel_size, std::int64_t stride, std::int64_t padding,
                           std::int64_t short_length) {
  TORCH_CHECK(stride > 0 && padding >= 0 && short_length > 0,
              "circular layer needs stride > 0, padding >= 0 and a non-empty signal");
  TORCH_CHECK(kernel_size - 2 * padding == stride, "circular layer does not tile the ring: kernel ",
              kernel_size, " - 2 * padding ", padding, " != stride ", stride);
  TORCH_CHECK(kernel_size <= stride * short_length, "circular layer kernel ", kernel_size,
              " is wider than its ring of ", stride * short_length);
}

torch::Tensor CircularGather(const torch::Tensor& long_signal, const torch::Tensor& weight,
                             const torch::Tensor& bias, std::int64_t stride, std::int64_t padding) {
  CheckTensors(long_signal, weight, bias, 1);
  const Sizes n{long_signal.size(0),          weight.size(1), weight.size(0), long_signal.size(2),
                long_signal.size(2) / stride, weight.size(2)};
  TORCH_CHECK(n.long_length == n.short_length * stride, "circular layer input length ",
              n.long_length, " is not a multiple of the stride ", stride);
  CheckCircularGeometry(n.kernel_size, stride, padding, n.short_length);
  torch::Tensor short_signal =
      torch::empty({n.batch, n.short_channels, n.short_length}, long_signal.options());
  AT_DISPATCH_FLOATING_TYPES(long_signal.scalar_type(), "CircularGather", [&] {
    Gather<scalar_t>(long_signal.data_ptr<scalar_t>(), weight.data_ptr<scalar_t>(),
                     DataOrNull<scalar_t>(bias), short_signal.data_ptr<scalar_t>(), n, stride,
                     padding);
  });
  return short_signal;
}

torch::Tensor CircularSpread(const torch::Tensor& short_signal, const torch::Tensor& weight,
                             const torch::Tensor& bias, std::int64_t stride, std::int64_t padding) {
  CheckTensors(short_signal, weight, bias, 0);
  const Sizes n{short_signal.size(0),          weight.size(1),       weight.size(0),
                short_signal.size(2) * stride, short_signal.size(2), weight.size(2)};
  CheckCircularGeometry(n.kernel_size, stride, padding, n.short_length);
  torch::Tensor long_signal =
      torch::empty({n.batch, n.long_channels, n.long_length}, short_signal.options());
  AT_DISPATCH_FLOATING_TYPES(short_signal.scalar_type(), "CircularSpread", [&] {
    Spread<scalar_t>(short_signal.data_ptr<scalar_t>(), weight.data_ptr<scalar_t>(),
                     DataOrNull<scalar_t>(bias), long_signal.data_ptr<scalar_t>(), n, stride,
                     padding);
  });
  return long_signal;
}

torch::Tensor CircularWeightGradient(const torch::Tensor& short_signal,
                                     const torch::Tensor& long_signal, std::int64_t kernel_size,
                                     std::int64_t stride, std::int64_t padding) {
  TORCH_CHECK(short_signal.dim() == 3 && long_signal.dim() == 3 &&
                  short_signal.size(0) == long_signal.size(0) &&
                  long_signal.size(2) == short_signal.size(2) * stride,
              "circular weight gradient: signals ", short_signal.sizes(), " and ",
              long_signal.sizes(), " do not fit stride ", stride);
  TORCH_CHECK(short_signal.is_contiguous() && long_signal.is_contiguous() &&
                  short_signal.device().is_cpu() && long_signal.device().is_cpu() &&
                  short_signal.scalar_type() == long_signal.scalar_type(),
              "circular layer kernels need contiguous CPU tensors of one dtype");
  const Sizes n{short_signal.size(0), long_signal.size(1),  short_signal.size(1),
                long_signal.size(2),  short_signal.size(2), kernel_size};
  CheckCircularGeometry(n.kernel_size, stride, padding, n.short_length);
  torch::Tensor gradient =
      torch::zeros({n.short_channels, n.long_channels, n.kernel_size}, short_signal.options());
  AT_DISPATCH_FLOATING_TYPES(short_signal.scalar_type(), "CircularWeightGradient", [&] {
    WeightGradient<scalar_t>(short_signal.data_ptr<scalar_t>(), long_signal.data_ptr<scalar_t>(),
                             gradient.data_ptr<scalar_t>(), n, stride, padding);
  });
  return gradient;
}

}  // namespace colav

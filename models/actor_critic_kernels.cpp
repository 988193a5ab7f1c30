#include "models/actor_critic_kernels.h"

#include <algorithm>
#include <cmath>
#include <vector>

// The 8-float vector type below is wider than the baseline ABI's registers; it never crosses a
// function boundary (all helpers are always_inline), so the ABI note GCC prints does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
// One AVX2+FMA clone and one baseline clone of each hot function, chosen at load time.
#define COLAV_MULTIVERSION __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define COLAV_MULTIVERSION
#endif
#define COLAV_INLINE inline __attribute__((always_inline))

namespace colav::kernels {
namespace {

constexpr int kLanes = 8;
using Vec = float __attribute__((vector_size(kLanes * sizeof(float))));
using UnalignedVec = float __attribute__((vector_size(kLanes * sizeof(float)), aligned(4)));

COLAV_INLINE Vec Load(const float* p) { return *reinterpret_cast<const UnalignedVec*>(p); }
COLAV_INLINE void Store(float* p, Vec v) { *reinterpret_cast<UnalignedVec*>(p) = v; }
// Written as a vector-scalar add: GCC lowers an 8-element initialiser to a chain of inserts, but
// this to one (scalar add and) broadcast.
COLAV_INLINE Vec Splat(float x) { return Vec{} + x; }

COLAV_INLINE float HorizontalSum(Vec v) {
  float sum = 0.0f;
  for (int i = 0; i < kLanes; ++i) sum += v[i];
  return sum;
}

// y[0:n] += a * x[0:n].
COLAV_INLINE void Axpy(float a, const float* x, float* y, int n) {
  int i = 0;
  const Vec va = Splat(a);
  for (; i + kLanes <= n; i += kLanes) Store(y + i, Load(y + i) + va * Load(x + i));
  for (; i < n; ++i) y[i] += a * x[i];
}

COLAV_INLINE float Dot(const float* x, const float* y, int n) {
  Vec acc{};
  int i = 0;
  for (; i + kLanes <= n; i += kLanes) acc += Load(x + i) * Load(y + i);
  float sum = HorizontalSum(acc);
  for (; i < n; ++i) sum += x[i] * y[i];
  return sum;
}

// tanh(x) = x P(x^2) / Q(x^2) on [-7.9, 7.9] (saturated beyond), Eigen's float approximation.
COLAV_INLINE Vec Tanh(Vec x) {
  constexpr float kClamp = 7.90531110763549805f;
  constexpr float kTiny = 0.0004f;
  const Vec clamped = x > kClamp ? Splat(kClamp) : (x < -kClamp ? Splat(-kClamp) : x);
  const Vec x2 = clamped * clamped;
  Vec p = Splat(-2.76076847742355e-16f);
  p = p * x2 + 2.00018790482477e-13f;
  p = p * x2 + -8.60467152213735e-11f;
  p = p * x2 + 5.12229709037114e-08f;
  p = p * x2 + 1.48572235717979e-05f;
  p = p * x2 + 6.37261928875436e-04f;
  p = p * x2 + 4.89352455891786e-03f;
  p = p * clamped;
  Vec q = Splat(1.19825839466702e-06f);
  q = q * x2 + 1.18534705686654e-04f;
  q = q * x2 + 2.26843463243900e-03f;
  q = q * x2 + 4.89352518554385e-03f;
  const Vec magnitude = x < 0 ? -x : x;
  return magnitude < kTiny ? x : p / q;
}

// One block of MatMul: rows m..m+kRows, columns n..n+kChunks*kLanes.
template <int kRows, int kChunks>
COLAV_INLINE void MatMulBlock(float* c, int ldc, const float* a, int a_row_stride, int a_col_stride,
                              const float* b, int ldb, int K, bool accumulate) {
  // Fully unrolled, so that the accumulators live in registers.
  Vec acc[kRows][kChunks] = {};
  for (int k = 0; k < K; ++k) {
    Vec b_row[kChunks];
#pragma GCC unroll 4
    for (int j = 0; j < kChunks; ++j) b_row[j] = Load(b + k * ldb + j * kLanes);
#pragma GCC unroll 4
    for (int i = 0; i < kRows; ++i) {
      const Vec a_ik = Splat(a[i * a_row_stride + k * a_col_stride]);
#pragma GCC unroll 4
      for (int j = 0; j < kChunks; ++j) acc[i][j] += a_ik * b_row[j];
    }
  }
#pragma GCC unroll 4
  for (int i = 0; i < kRows; ++i) {
#pragma GCC unroll 4
    for (int j = 0; j < kChunks; ++j) {
      float* out = c + i * ldc + j * kLanes;
      Store(out, accumulate ? Load(out) + acc[i][j] : acc[i][j]);
    }
  }
}

template <int kRows>
COLAV_INLINE void MatMulRows(float* c, int ldc, const float* a, int a_row_stride, int a_col_stride,
                             const float* b, int ldb, int N, int K, bool accumulate) {
  int n = 0;
  for (; n + 2 * kLanes <= N; n += 2 * kLanes) {
    MatMulBlock<kRows, 2>(c + n, ldc, a, a_row_stride, a_col_stride, b + n, ldb, K, accumulate);
  }
  for (; n + kLanes <= N; n += kLanes) {
    MatMulBlock<kRows, 1>(c + n, ldc, a, a_row_stride, a_col_stride, b + n, ldb, K, accumulate);
  }
}

// The last N % 8 columns of C, from B's tail columns copied into a zero-padded K x 8 panel.
template <int kRows>
COLAV_INLINE void MatMulTailRows(float* c, int ldc, const float* a, int a_row_stride,
                                 int a_col_stride, const float* panel, int columns, int K,
                                 bool accumulate) {
  float block[kRows * kLanes];
  MatMulBlock<kRows, 1>(block, kLanes, a, a_row_stride, a_col_stride, panel, kLanes, K, false);
  for (int i = 0; i < kRows; ++i) {
    for (int j = 0; j < columns; ++j) {
      c[i * ldc + j] = (accumulate ? c[i * ldc + j] : 0.0f) + block[i * kLanes + j];
    }
  }
}

}  // namespace

COLAV_MULTIVERSION
void MatMul(float* c, int ldc, const float* a, int a_row_stride, int a_col_stride, const float* b,
            int ldb, int M, int N, int K, bool accumulate) {
  constexpr int kRowBlock = 4;
  int m = 0;
  for (; m + kRowBlock <= M; m += kRowBlock) {
    MatMulRows<kRowBlock>(c + m * ldc, ldc, a + m * a_row_stride, a_row_stride, a_col_stride, b,
                          ldb, N, K, accumulate);
  }
  if (m + 2 <= M) {  // a pair of rows shares each load of B
    MatMulRows<2>(c + m * ldc, ldc, a + m * a_row_stride, a_row_stride, a_col_stride, b, ldb, N, K,
                  accumulate);
    m += 2;
  }
  for (; m < M; ++m) {
    MatMulRows<1>(c + m * ldc, ldc, a + m * a_row_stride, a_row_stride, a_col_stride, b, ldb, N, K,
                  accumulate);
  }
  const int tail_start = N / kLanes * kLanes;
  const int tail = N - tail_start;
  if (tail == 0) return;
  thread_local std::vector<float> panel;
  panel.assign(static_cast<std::size_t>(K) * kLanes, 0.0f);
  for (int k = 0; k < K; ++k) {
    std::copy_n(b + k * ldb + tail_start, tail, &panel[static_cast<std::size_t>(k) * kLanes]);
  }
  c += tail_start;
  for (m = 0; m + kRowBlock <= M; m += kRowBlock) {
    MatMulTailRows<kRowBlock>(c + m * ldc, ldc, a + m * a_row_stride, a_row_stride, a_col_stride,
                              panel.data(), tail, K, accumulate);
  }
  for (; m < M; ++m) {
    MatMulTailRows<1>(c + m * ldc, ldc, a + m * a_row_stride, a_row_stride, a_col_stride,
                      panel.data(), tail, K, accumulate);
  }
}

void LinearForward(const float* weight, const float* bias, const float* x, int in, int out, int B,
                   float* y) {
  for (int o = 0; o < out; ++o) std::fill(y + o * B, y + (o + 1) * B, bias[o]);
  MatMul(y, B, weight, in, 1, x, B, out, B, in, /*accumulate=*/true);
}

COLAV_MULTIVERSION
void LinearBackward(const float* weight, const float* x, const float* dy, int in, int out, int B,
                    float* d_weight, float* d_bias, float* dx, float* x_transposed) {
  for (int o = 0; o < out; ++o) {
    const float* row = dy + o * B;
    Vec acc{};
    int b = 0;
    for (; b + kLanes <= B; b += kLanes) acc += Load(row + b);
    float sum = HorizontalSum(acc);
    for (; b < B; ++b) sum += row[b];
    d_bias[o] = sum;
  }
  // d_weight [out, in] = dy [out, B] x^T [B, in]
  Transpose(x, in, B, x_transposed);
  MatMul(d_weight, in, dy, B, 1, x_transposed, in, out, in, B, /*accumulate=*/false);
  // dx [in, B] = W^T [in, out] dy [out, B]
  if (dx != nullptr) MatMul(dx, B, weight, 1, in, dy, B, in, B, out, /*accumulate=*/false);
}

COLAV_MULTIVERSION
void TanhInPlace(float* x, int n) {
  int i = 0;
  for (; i + kLanes <= n; i += kLanes) Store(x + i, Tanh(Load(x + i)));
  for (; i < n; ++i) x[i] = Tanh(Splat(x[i]))[0];
}

COLAV_MULTIVERSION
void TanhBackwardInPlace(float* grad, const float* y, int n) {
  int i = 0;
  for (; i + kLanes <= n; i += kLanes) {
    const Vec yi = Load(y + i);
    Store(grad + i, Load(grad + i) * (1.0f - yi * yi));
  }
  for (; i < n; ++i) grad[i] *= 1.0f - y[i] * y[i];
}

COLAV_MULTIVERSION
void ReluInPlace(float* x, int n) {
  int i = 0;
  for (; i + kLanes <= n; i += kLanes) {
    const Vec v = Load(x + i);
    Store(x + i, v > 0.0f ? v : Vec{});
  }
  for (; i < n; ++i) x[i] = std::max(x[i], 0.0f);
}

COLAV_MULTIVERSION
void ReluBackwardInPlace(float* grad, const float* y, int n) {
  int i = 0;
  for (; i + kLanes <= n; i += kLanes) {
    Store(grad + i, Load(y + i) > 0.0f ? Load(grad + i) : Vec{});
  }
  for (; i < n; ++i) {
    if (y[i] <= 0.0f) grad[i] = 0.0f;
  }
}

void Transpose(const float* src, int rows, int cols, float* dst) {
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) dst[c * rows + r] = src[r * cols + c];
  }
}

COLAV_MULTIVERSION
void CircularConvForward(const CircularConvShape& shape, const float* weight, const float* bias,
                         const float* x, int B, float* y) {
  const int out_length = shape.out_length();
  for (int co = 0; co < shape.out_channels; ++co) {
    for (int l = 0; l < out_length; ++l) {
      float* y_row = y + (co * out_length + l) * B;
      std::fill(y_row, y_row + B, bias[co]);
      for (int ci = 0; ci < shape.in_channels; ++ci) {
        const float* w = weight + (co * shape.in_channels + ci) * shape.kernel;
        for (int k = 0; k < shape.kernel; ++k) {
          const int position =
              ((l * shape.stride + k - shape.padding) % shape.length + shape.length) % shape.length;
          Axpy(w[k], x + (ci * shape.length + position) * B, y_row, B);
        }
      }
    }
  }
}

COLAV_MULTIVERSION
void CircularConvBackward(const CircularConvShape& shape, const float* weight, const float* x,
                          const float* dy, int B, float* d_weight, float* d_bias, float* dx) {
  const int out_length = shape.out_length();
  std::fill(d_weight, d_weight + shape.out_channels * shape.in_channels * shape.kernel, 0.0f);
  if (dx != nullptr) std::fill(dx, dx + shape.in_channels * shape.length * B, 0.0f);
  for (int co = 0; co < shape.out_channels; ++co) {
    float bias_sum = 0.0f;
    for (int l = 0; l < out_length; ++l) {
      const float* dy_row = dy + (co * out_length + l) * B;
      for (int b = 0; b < B; ++b) bias_sum += dy_row[b];
      for (int ci = 0; ci < shape.in_channels; ++ci) {
        const int w_offset = (co * shape.in_channels + ci) * shape.kernel;
        for (int k = 0; k < shape.kernel; ++k) {
          const int position =
              ((l * shape.stride + k - shape.padding) % shape.length + shape.length) % shape.length;
          const int x_row = (ci * shape.length + position) * B;
          d_weight[w_offset + k] += Dot(dy_row, x + x_row, B);
          if (dx != nullptr) Axpy(weight[w_offset + k], dy_row, dx + x_row, B);
        }
      }
    }
    d_bias[co] = bias_sum;
  }
}

COLAV_MULTIVERSION
double SumOfSquares(const float* x, int n) {
  Vec acc{};
  int i = 0;
  for (; i + kLanes <= n; i += kLanes) acc += Load(x + i) * Load(x + i);
  double sum = HorizontalSum(acc);
  for (; i < n; ++i) sum += static_cast<double>(x[i]) * x[i];
  return sum;
}

bool AllFinite(const float* x, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(x[i])) return false;
  }
  return true;
}

// sqrt of each lane. GCC turns the lane loop into one vsqrtps (sqrtps in the baseline clone):
// this file is compiled with -fno-math-errno, so a square root needs no errno check.
COLAV_INLINE Vec Sqrt(Vec v) {
  Vec root;
  for (int i = 0; i < kLanes; ++i) root[i] = __builtin_sqrtf(v[i]);
  return root;
}

COLAV_MULTIVERSION
void AdamUpdate(const AdamCoefficients& coefficients, const float* grad, float* exp_avg,
                float* exp_avg_sq, float* param, int n) {
  const float scale = coefficients.gradient_scale;
  const float b1 = coefficients.beta1;
  const float b2 = coefficients.beta2;
  const float correction = coefficients.sqrt_bias_correction2;
  int i = 0;
  for (; i + kLanes <= n; i += kLanes) {
    const Vec g = Load(grad + i) * scale;
    const Vec m = Load(exp_avg + i) * b1 + g * (1.0f - b1);
    const Vec v = Load(exp_avg_sq + i) * b2 + g * g * (1.0f - b2);
    Store(exp_avg + i, m);
    Store(exp_avg_sq + i, v);
    Store(param + i, Load(param + i) -
                         coefficients.step_size * (m / (Sqrt(v) / correction + coefficients.eps)));
  }
  for (; i < n; ++i) {
    const float g = grad[i] * scale;
    exp_avg[i] = exp_avg[i] * b1 + g * (1.0f - b1);
    exp_avg_sq[i] = exp_avg_sq[i] * b2 + g * g * (1.0f - b2);
    param[i] -= coefficients.step_size *
                (exp_avg[i] / (std::sqrt(exp_avg_sq[i]) / correction + coefficients.eps));
  }
}

}  // namespace colav::kernels

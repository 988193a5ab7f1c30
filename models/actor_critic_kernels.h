// Vectorised float kernels for the hand-written actor-critic passes (actor_critic_fast.h).
//
// The networks are tiny (18 -> 128 -> 64 -> 32) and PPO updates them 375,000 times on batches of
// 32, so LibTorch's per-operator overhead (several microseconds per op, hundreds of ops per
// update) would dominate. These kernels work on "feature-major" activations: a batch of B samples
// of n features is an [n, B] row-major array, so every inner loop runs over the batch with
// contiguous vector loads. Each kernel is compiled twice (AVX2+FMA and baseline x86-64) and the
// right one is picked at load time.
#pragma once

namespace colav::kernels {

/// C[m, n] = (accumulate ? C[m, n] : 0) + sum_k A(m, k) * B[k, n] for m < M, n < N, k < K, where
/// A(m, k) = a[m * a_row_stride + k * a_col_stride] (so A may be a transposed view), B is
/// row-major with leading dimension ldb and C row-major with leading dimension ldc.
void MatMul(float* c, int ldc, const float* a, int a_row_stride, int a_col_stride, const float* b,
            int ldb, int M, int N, int K, bool accumulate);

/// y[o, :] = bias[o] + sum_i W[o, i] x[i, :]: a Linear layer on x [in, B] (W is [out, in]).
void LinearForward(const float* weight, const float* bias, const float* x, int in, int out, int B,
                   float* y);

/// Gradients of a Linear layer from dy [out, B]: d_weight [out, in] and d_bias [out] (written,
/// not accumulated), and dx [in, B] unless it is null. `x_transposed` is scratch for B * in floats.
void LinearBackward(const float* weight, const float* x, const float* dy, int in, int out, int B,
                    float* d_weight, float* d_bias, float* dx, float* x_transposed);

/// tanh of n values in place (a rational approximation accurate to a few float ulps).
void TanhInPlace(float* x, int n);
/// grad *= 1 - y^2, the derivative of y = tanh(x), for n values.
void TanhBackwardInPlace(float* grad, const float* y, int n);
void ReluInPlace(float* x, int n);
/// grad = 0 where y <= 0 (y = relu(x)), for n values.
void ReluBackwardInPlace(float* grad, const float* y, int n);

/// dst [cols, rows] = transpose of src [rows, cols].
void Transpose(const float* src, int rows, int cols, float* dst);

/// A Conv1d with circular padding on feature-major x [in_channels * length, B]:
/// y[co * out_length + l, :] = bias[co] + sum_ci,k w[co, ci, k] x[ci * length + (l * stride + k -
/// padding) mod length, :], with out_length = (length + 2 padding - kernel) / stride + 1.
struct CircularConvShape {
  int in_channels;
  int out_channels;
  int kernel;
  int stride;
  int padding;
  int length;  ///< input length
  int out_length() const { return (length + 2 * padding - kernel) / stride + 1; }
};
void CircularConvForward(const CircularConvShape& shape, const float* weight, const float* bias,
                         const float* x, int B, float* y);
/// Gradients from dy [out_channels * out_length, B]: d_weight and d_bias written, dx (if not null)
/// written.
void CircularConvBackward(const CircularConvShape& shape, const float* weight, const float* x,
                          const float* dy, int B, float* d_weight, float* d_bias, float* dx);

/// Sum of squares of n values (for the global gradient norm).
double SumOfSquares(const float* x, int n);
/// False if any of n values is NaN or infinite.
bool AllFinite(const float* x, int n);

/// One Adam step on n parameters (torch.optim.Adam without weight decay or amsgrad), with the
/// gradient g = gradient_scale * grad (the gradient-norm clipping, folded in):
/// m = b1 m + (1 - b1) g; v = b2 v + (1 - b2) g^2;
/// p -= step_size * m / (sqrt(v) / sqrt_bias_correction2 + eps).
struct AdamCoefficients {
  float beta1;
  float beta2;
  float eps;
  float step_size;              ///< lr / (1 - beta1^t)
  float sqrt_bias_correction2;  ///< sqrt(1 - beta2^t)
  float gradient_scale = 1.0f;
};
void AdamUpdate(const AdamCoefficients& coefficients, const float* grad, float* exp_avg,
                float* exp_avg_sq, float* param, int n);

}  // namespace colav::kernels

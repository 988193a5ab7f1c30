#include "models/recurrent_fast.h"

#include <algorithm>
#include <cmath>

#include "models/actor_critic_kernels.h"
#include "models/float_data.h"

namespace colav {
namespace {

float Sigmoid(float x) { return 1.0f / (1.0f + std::exp(-x)); }

// Row sums of the [rows, columns] array `a` into `sums`.
void RowSums(const float* a, int rows, int columns, float* sums) {
  for (int i = 0; i < rows; ++i) {
    float sum = 0.0f;
    for (int c = 0; c < columns; ++c) sum += a[static_cast<std::ptrdiff_t>(i) * columns + c];
    sums[i] = sum;
  }
}

// d_weight [M, K] = d_out [M, N] * x^T for x [K, N] (both feature-major), via x transposed.
void WeightGradient(const float* d_out, const float* x, int M, int K, int N, float* transposed,
                    float* d_weight) {
  kernels::Transpose(x, K, N, transposed);
  kernels::MatMul(d_weight, K, d_out, N, 1, transposed, K, M, K, N, /*accumulate=*/false);
}

}  // namespace

FastGru::FastGru(torch::nn::GRUCell& cell, std::vector<torch::Tensor> gradients, int max_columns)
    : input_size_(static_cast<int>(cell->weight_ih.size(1))),
      state_size_(static_cast<int>(cell->weight_hh.size(1))),
      max_columns_(max_columns),
      weight_ih_(cell->weight_ih),
      weight_hh_(cell->weight_hh),
      bias_ih_(cell->bias_ih),
      bias_hh_(cell->bias_hh),
      gradients_(std::move(gradients)) {
  TORCH_CHECK(gradients_.size() == 4, "FastGru needs the gradients of its 4 parameters");
  const std::size_t gates = static_cast<std::size_t>(3 * state_size_) * max_columns;
  const std::size_t states = static_cast<std::size_t>(state_size_) * max_columns;
  for (auto* buffer : {&input_gates_, &recurrent_gates_, &d_input_gates_, &d_recurrent_gates_}) {
    buffer->resize(gates);
  }
  for (auto* buffer : {&previous_, &reset_gate_, &update_gate_, &candidate_, &states_}) {
    buffer->resize(states);
  }
  d_previous_.resize(states);
  d_recurrent_product_.resize(states);
  weight_hh_transposed_.resize(static_cast<std::size_t>(3 * state_size_) * state_size_);
  transposed_.resize(static_cast<std::size_t>(std::max(input_size_, state_size_)) * max_columns);
}

const float* FastGru::ForwardSequences(const float* x, const float* initial,
                                       const std::uint8_t* reset, int L, int S) {
  const int C = L * S;
  const int H = state_size_;
  TORCH_CHECK(C <= max_columns_, "more columns than FastGru's max_columns");
  L_ = L;
  S_ = S;
  reset_ = reset;
  kernels::LinearForward(FloatData(weight_ih_), FloatData(bias_ih_), x, input_size_, 3 * H, C,
                         input_gates_.data());
  kernels::Transpose(FloatData(weight_hh_), 3 * H, H, weight_hh_transposed_.data());
  const float* gi = input_gates_.data();
  float* gh = recurrent_gates_.data();
  const float* b_hh = FloatData(bias_hh_);
  for (int t = 0; t < L; ++t) {
    const int c0 = t * S;
    for (int j = 0; j < H; ++j) {
      for (int s = 0; s < S; ++s) {
        const bool zero = reset != nullptr && reset[c0 + s] != 0;
        const float before = t == 0 ? initial[j * S + s] : states_[j * C + c0 - S + s];
        previous_[j * C + c0 + s] = zero ? 0.0f : before;
      }
    }
    // The step's recurrent projections, row s = W_hh h_s: S rows of 3H values.
    kernels::MatMul(gh + c0 * 3 * H, 3 * H, previous_.data() + c0, 1, C,
                    weight_hh_transposed_.data(), 3 * H, S, 3 * H, H, /*accumulate=*/false);
    for (int j = 0; j < H; ++j) {
      for (int s = 0; s < S; ++s) {
        const int c = c0 + s;
        float* gh_c = gh + c * 3 * H;
        for (int g = 0; g < 3; ++g) gh_c[g * H + j] += b_hh[g * H + j];
        const float r = Sigmoid(gi[j * C + c] + gh_c[j]);
        const float z = Sigmoid(gi[(H + j) * C + c] + gh_c[H + j]);
        const float n = std::tanh(gi[(2 * H + j) * C + c] + r * gh_c[2 * H + j]);
        reset_gate_[j * C + c] = r;
        update_gate_[j * C + c] = z;
        candidate_[j * C + c] = n;
        states_[j * C + c] = (1.0f - z) * n + z * previous_[j * C + c];
      }
    }
  }
  return states_.data();
}

void FastGru::BackwardSequences(const float* x, float* d_states, float* d_x) {
  const int S = S_;
  const int C = L_ * S;
  const int H = state_size_;
  for (int t = L_ - 1; t >= 0; --t) {
    const int c0 = t * S;
    for (int j = 0; j < H; ++j) {
      for (int s = 0; s < S; ++s) {
        const int c = c0 + s;
        const int k = j * C + c;
        const float dh = d_states[k];
        const float r = reset_gate_[k], z = update_gate_[k], n = candidate_[k];
        const float dn = dh * (1.0f - z) * (1.0f - n * n);
        const float dz = dh * (previous_[k] - n) * z * (1.0f - z);
        const float dr = dn * recurrent_gates_[c * 3 * H + 2 * H + j] * r * (1.0f - r);
        d_input_gates_[k] = dr;
        d_input_gates_[(H + j) * C + c] = dz;
        d_input_gates_[(2 * H + j) * C + c] = dn;
        d_recurrent_gates_[k] = dr;
        d_recurrent_gates_[(H + j) * C + c] = dz;
        d_recurrent_gates_[(2 * H + j) * C + c] = dn * r;
        d_previous_[k] = dh * z;
      }
    }
    if (t == 0) break;  // the first state is the rollout's record, a constant
    // d previous += W_hh^T d_gh; it reaches the step before unless an episode starts here.
    // Row s of the product: (W_hh^T d_gh)_s, S rows of H values.
    float* d_recurrent = d_recurrent_product_.data();
    kernels::MatMul(d_recurrent, H, d_recurrent_gates_.data() + c0, 1, C, FloatData(weight_hh_), H,
                    S, H, 3 * H, /*accumulate=*/false);
    for (int j = 0; j < H; ++j) {
      for (int s = 0; s < S; ++s) {
        const int k = j * C + c0 + s;
        d_previous_[k] += d_recurrent[s * H + j];
        if (reset_ != nullptr && reset_[c0 + s] != 0) continue;
        d_states[k - S] += d_previous_[k];
      }
    }
  }
  WeightGradient(d_input_gates_.data(), x, 3 * H, input_size_, C, transposed_.data(),
                 FloatData(gradients_[0]));
  WeightGradient(d_recurrent_gates_.data(), previous_.data(), 3 * H, H, C, transposed_.data(),
                 FloatData(gradients_[1]));
  RowSums(d_input_gates_.data(), 3 * H, C, FloatData(gradients_[2]));
  RowSums(d_recurrent_gates_.data(), 3 * H, C, FloatData(gradients_[3]));
  kernels::MatMul(d_x, C, FloatData(weight_ih_), 1, input_size_, d_input_gates_.data(), C,
                  input_size_, C, 3 * H, /*accumulate=*/false);
}

}  // namespace colav

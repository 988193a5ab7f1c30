// Hand-written forward and backward passes of the actor-critic's GRU cell (torch.nn.GRUCell,
// models/actor_critic.h) over the sequences of a PPO minibatch, on the model's own parameters.
//
// Activations are feature-major like those of actor_critic_fast.h: a minibatch of S sequences of
// L steps is an [n, L * S] array whose column t * S + s holds step t of sequence s, so the input
// projections of all steps are one matrix product and each step's recurrent product is a block of
// S columns (computed transposed, S rows of 3 * state_size: the vector lanes run along the longer
// side). Per step (gates r, z, n; PyTorch's equations):
//   r = sigmoid(W_ir x + b_ir + W_hr h + b_hr)    z = sigmoid(W_iz x + b_iz + W_hz h + b_hz)
//   n = tanh(W_in x + b_in + r * (W_hn h + b_hn))  h' = (1 - z) * n + z * h
// where h is the previous step's state, or 0 where an episode starts. Backpropagation runs
// through the L steps of each sequence and stops at its first state, which the rollout recorded
// (truncated backpropagation through time).
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <vector>

namespace colav {

class FastGru {
 public:
  /// Binds to `cell`'s parameters and writes its gradients into `gradients` (tensors of the same
  /// shapes, in the order weight_ih, weight_hh, bias_ih, bias_hh), for up to max_columns
  /// columns (L * S).
  FastGru(torch::nn::GRUCell& cell, std::vector<torch::Tensor> gradients, int max_columns);

  int input_size() const { return input_size_; }
  int state_size() const { return state_size_; }

  /// S sequences of L steps: x [input_size, L * S] and initial [state_size, S] (the states before
  /// step 0); reset[t * S + s] != 0 (or reset null: never) zeroes the state before step t of
  /// sequence s. Returns the states after each step, [state_size, L * S], valid until the next
  /// call, and keeps what BackwardSequences needs.
  const float* ForwardSequences(const float* x, const float* initial, const std::uint8_t* reset,
                                int L, int S);
  /// Backward of the last ForwardSequences from d_states [state_size, L * S], the loss's gradient
  /// with respect to each step's state (overwritten: the gradient flowing back through later steps
  /// is added in). Writes the parameters' gradients and d_x [input_size, L * S].
  void BackwardSequences(const float* x, float* d_states, float* d_x);

 private:
  int input_size_, state_size_, max_columns_;
  torch::Tensor weight_ih_, weight_hh_, bias_ih_, bias_hh_;
  std::vector<torch::Tensor> gradients_;
  int L_ = 0, S_ = 0;
  const std::uint8_t* reset_ = nullptr;
  // [3 * state_size, L * S]: input projections, then their gradients.
  std::vector<float> input_gates_;
  // [L * S, 3 * state_size]: the recurrent projections, transposed from the layout of the rest:
  // each step's product is computed as [S, state_size] x W_hh^T, because a step has only S
  // columns (2 in the default minibatch), too few for the vector lanes, and 3 * state_size rows.
  std::vector<float> recurrent_gates_;
  // [state_size, L * S]: the state each step starts from, its gates r, z, n and its result.
  std::vector<float> previous_, reset_gate_, update_gate_, candidate_, states_;
  // [3 * state_size, L * S]: the gradients of the projections; d_previous_ like previous_;
  // transposed_: scratch for the weight gradients' transposed inputs.
  std::vector<float> d_input_gates_, d_recurrent_gates_, d_previous_, transposed_;
  // W_hh^T [state_size, 3 * state_size] for the forward's step products; the backward's step
  // product ([S, state_size], rows of W_hh^T d_gh) before it is added to d_previous_.
  std::vector<float> weight_hh_transposed_, d_recurrent_product_;
};

}  // namespace colav

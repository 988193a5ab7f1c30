// The encoder's circularly padded Conv1d, with its own forward and backward on the ring kernels
// (models/circular_kernels.h).
//
// Same semantics as torch::nn::Conv1d with padding_mode kCircular (spec reference-learning 1.2):
//   y[b, o, i] = bias[o] + sum_{c, t} weight[o, c, t] x[b, c, (stride i + t - padding) mod N],
// for layers that tile the ring (kernel - 2 * padding == stride, output length N / stride).
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <ostream>

namespace colav {

// x [B, Cin, N], weight [Cout, Cin, k], bias [Cout] -> y [B, Cout, N / stride].
class CircularConv1dFunction : public torch::autograd::Function<CircularConv1dFunction> {
 public:
  static torch::Tensor forward(torch::autograd::AutogradContext* context, const torch::Tensor& x,
                               const torch::Tensor& weight, const torch::Tensor& bias,
                               std::int64_t stride, std::int64_t padding);
  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* context,
                                                 torch::autograd::variable_list output_gradients);
};

struct CircularConv1dOptions {
  CircularConv1dOptions(std::int64_t in_channels, std::int64_t out_channels,
                        std::int64_t kernel_size)
      : in_channels_(in_channels), out_channels_(out_channels), kernel_size_(kernel_size) {}
  TORCH_ARG(std::int64_t, in_channels);
  TORCH_ARG(std::int64_t, out_channels);
  TORCH_ARG(std::int64_t, kernel_size);
  TORCH_ARG(std::int64_t, stride) = 1;
  // Columns wrapped around each end of the input.
  TORCH_ARG(std::int64_t, padding) = 0;
};

// Parameters `weight` [Cout, Cin, k] and `bias` [Cout], initialised as torch::nn::Conv1d's.
class CircularConv1dImpl : public torch::nn::Module {
 public:
  explicit CircularConv1dImpl(CircularConv1dOptions options);

  // x [B, Cin, N] -> [B, Cout, N / stride].
  torch::Tensor forward(const torch::Tensor& x);

  void reset_parameters();
  void pretty_print(std::ostream& stream) const override;
  const CircularConv1dOptions& options() const { return options_; }

  torch::Tensor weight;
  torch::Tensor bias;

 private:
  CircularConv1dOptions options_;
};
TORCH_MODULE(CircularConv1d);

// LibTorch's Linear and convolution initialisation (spec reference-learning 1.8), for Linear,
// Conv1d and ConvTranspose1d layouts alike: Kaiming-uniform with a = sqrt(5) on the weight, bias
// uniform in +-1/sqrt(fan_in), fan_in being the weight's dim 1 times the kernel size. Drawn from
// `generator` (LibTorch's global one when none is given) with torch::nn::init's arithmetic, so
// the values are those torch::nn::init draws from the same generator state.
void ResetConvolutionParameters(torch::Tensor& weight, torch::Tensor& bias,
                                const c10::optional<torch::Generator>& generator = c10::nullopt);

// Redraws, from `generator`, the parameters of every layer of `module` that has a weight and a
// bias (Linear, CircularConv1d, CircularConvTranspose1d) with ResetConvolutionParameters, in
// module order. LibTorch's module constructors draw from the global generator; for a module whose
// layers are registered as they are made, this gives the weights the constructors would have
// drawn with the global generator in `generator`'s state.
void RedrawLayerParameters(torch::nn::Module& module, torch::Generator& generator);

}  // namespace colav

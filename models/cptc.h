// CPTC-1D: the circularly padded transposed 1-D convolution of the paper's decoders.
//
// A scan is a ring of 180 rays: ray 179 neighbours ray 0. The encoder's circular Conv1d respects
// that; its transpose has to as well, or the decoder draws seams at the ends of the scan. The
// paper's recipe wraps the input with columns from the opposite end, applies the transposed
// convolution (with its own padding) and crops the excess. This project wraps the columns truly
// (the reference code put them back on the side they came from, which replicates edges; spec
// README, "CPTC-1D"), and then the result is exactly the adjoint of the circular Conv1d with the
// same weights, and shift-equivariant: rolling the input by one column rolls the output by one
// stride.
//
// The layer computes that adjoint directly on the ring (models/circular_kernels.h) rather than
// through padded copies and LibTorch's transposed convolution; the TorchScript export writes the
// recipe itself, and the tests check that both agree.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <ostream>

namespace colav {

// How a decoder's transposed convolutions treat the ends of the scan: wrapped (CPTC), or plain
// zero padding, kept for the paper's zero-padding-versus-CPTC comparison figure.
enum class DecoderPadding { kCircular, kZero };

// For the recipe: how many input columns a kept output reaches past each end of the input, i.e.
// how many columns to wrap, floor((kernel - 1 - padding) / stride); the crop is that many strides.
// 1 for both of the paper's layer shapes (k45 s15 p15 and k3 s1 p1), where the reference's
// round((kernel - 1) / (2 stride)) agrees.
std::int64_t CptcWrapWidth(std::int64_t kernel_size, std::int64_t stride, std::int64_t padding);

// Autograd function y = CPTC(z; weight, bias) with an explicit backward.
//   z [B, Cin, L], weight [Cin, Cout, k] (ConvTranspose1d layout), bias [Cout]
//   -> y [B, Cout, stride * L].
// `padding` is the ConvTranspose1d's own padding; the layer tiles the ring only when
// kernel - 2 * padding == stride, which is checked.
class CircularConvTranspose1dFunction
    : public torch::autograd::Function<CircularConvTranspose1dFunction> {
 public:
  static torch::Tensor forward(torch::autograd::AutogradContext* context, const torch::Tensor& z,
                               const torch::Tensor& weight, const torch::Tensor& bias,
                               std::int64_t stride, std::int64_t padding);
  static torch::autograd::variable_list backward(torch::autograd::AutogradContext* context,
                                                 torch::autograd::variable_list output_gradients);
};

struct CircularConvTranspose1dOptions {
  CircularConvTranspose1dOptions(std::int64_t in_channels, std::int64_t out_channels,
                                 std::int64_t kernel_size)
      : in_channels_(in_channels), out_channels_(out_channels), kernel_size_(kernel_size) {}
  TORCH_ARG(std::int64_t, in_channels);
  TORCH_ARG(std::int64_t, out_channels);
  TORCH_ARG(std::int64_t, kernel_size);
  TORCH_ARG(std::int64_t, stride) = 1;
  // The ConvTranspose1d's own padding (cropped from both ends of its output).
  TORCH_ARG(std::int64_t, padding) = 0;
  // kZero turns the layer into a plain ConvTranspose1d with the same output length.
  TORCH_ARG(DecoderPadding, padding_mode) = DecoderPadding::kCircular;
};

// A transposed Conv1d layer whose ends wrap around (or, with kZero, are zero padded). Parameters
// `weight` [Cin, Cout, k] and `bias` [Cout] are initialised as torch::nn::ConvTranspose1d's.
class CircularConvTranspose1dImpl : public torch::nn::Module {
 public:
  explicit CircularConvTranspose1dImpl(CircularConvTranspose1dOptions options);

  // z [B, Cin, L] -> [B, Cout, stride * L].
  torch::Tensor forward(const torch::Tensor& z);

  // torch::nn::ConvTranspose1d's initialisation.
  void reset_parameters();
  void pretty_print(std::ostream& stream) const override;
  const CircularConvTranspose1dOptions& options() const { return options_; }

  torch::Tensor weight;
  torch::Tensor bias;

 private:
  CircularConvTranspose1dOptions options_;
};
TORCH_MODULE(CircularConvTranspose1d);

}  // namespace colav

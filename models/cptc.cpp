#include "models/cptc.h"

#include <algorithm>

#include "models/circular_conv.h"
#include "models/circular_kernels.h"

namespace colav {

std::int64_t CptcWrapWidth(std::int64_t kernel_size, std::int64_t stride, std::int64_t padding) {
  return std::max<std::int64_t>(0, (kernel_size - 1 - padding) / stride);
}

torch::Tensor CircularConvTranspose1dFunction::forward(torch::autograd::AutogradContext* context,
                                                       const torch::Tensor& z,
                                                       const torch::Tensor& weight,
                                                       const torch::Tensor& bias,
                                                       std::int64_t stride, std::int64_t padding) {
  const torch::Tensor z_contiguous = z.contiguous();
  const torch::Tensor weight_contiguous = weight.contiguous();
  context->save_for_backward({z_contiguous, weight_contiguous});
  context->saved_data[kStrideKey] = stride;
  context->saved_data[kPaddingKey] = padding;
  return CircularSpread(z_contiguous, weight_contiguous, bias.contiguous(), stride, padding);
}

// CPTC spreads z along the ring links, so its input gradient gathers the output gradient along
// the same links (the circular Conv1d with the same weight), and its weight gradient correlates z
// with the output gradient over them.
torch::autograd::variable_list CircularConvTranspose1dFunction::backward(
    torch::autograd::AutogradContext* context, torch::autograd::variable_list output_gradients) {
  const auto saved = context->get_saved_variables();
  const torch::Tensor& z = saved[0];
  const torch::Tensor& weight = saved[1];
  const std::int64_t stride = context->saved_data[kStrideKey].toInt();
  const std::int64_t padding = context->saved_data[kPaddingKey].toInt();
  const torch::Tensor gradient = output_gradients[0].contiguous();

  torch::Tensor z_gradient, weight_gradient, bias_gradient;
  if (context->needs_input_grad(0)) {
    z_gradient = CircularGather(gradient, weight, torch::Tensor(), stride, padding);
  }
  if (context->needs_input_grad(1)) {
    weight_gradient = CircularWeightGradient(z, gradient, weight.size(2), stride, padding);
  }
  if (context->needs_input_grad(2)) bias_gradient = gradient.sum(at::IntArrayRef{0, 2});
  // No gradients for stride and padding.
  return {z_gradient, weight_gradient, bias_gradient, torch::Tensor(), torch::Tensor()};
}

CircularConvTranspose1dImpl::CircularConvTranspose1dImpl(CircularConvTranspose1dOptions options)
    : options_(options) {
  weight = register_parameter(
      "weight",
      torch::empty({options_.in_channels(), options_.out_channels(), options_.kernel_size()}));
  bias = register_parameter("bias", torch::empty({options_.out_channels()}));
  reset_parameters();
}

torch::Tensor CircularConvTranspose1dImpl::forward(const torch::Tensor& z) {
  switch (options_.padding_mode()) {
    case DecoderPadding::kCircular:
      return CircularConvTranspose1dFunction::apply(z, weight, bias, options_.stride(),
                                                    options_.padding());
    case DecoderPadding::kZero:
      return torch::conv_transpose1d(z, weight, bias, options_.stride(), options_.padding());
  }
  TORCH_CHECK(false, "unknown DecoderPadding");
}

void CircularConvTranspose1dImpl::reset_parameters() { ResetConvolutionParameters(weight, bias); }

void CircularConvTranspose1dImpl::pretty_print(std::ostream& stream) const {
  stream << "colav::CircularConvTranspose1d(" << options_.in_channels() << ", "
         << options_.out_channels() << ", kernel_size=" << options_.kernel_size()
         << ", stride=" << options_.stride() << ", padding=" << options_.padding()
         << ", padding_mode="
         << (options_.padding_mode() == DecoderPadding::kCircular ? "circular" : "zeros") << ")";
}

}  // namespace colav

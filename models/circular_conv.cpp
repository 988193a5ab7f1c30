#include "models/circular_conv.h"

#include <cmath>
#include <memory>
#include <string>
#include <tuple>

#include "models/circular_kernels.h"

namespace colav {

torch::Tensor CircularConv1dFunction::forward(torch::autograd::AutogradContext* context,
                                              const torch::Tensor& x, const torch::Tensor& weight,
                                              const torch::Tensor& bias, std::int64_t stride,
                                              std::int64_t padding) {
  const torch::Tensor x_contiguous = x.contiguous();
  const torch::Tensor weight_contiguous = weight.contiguous();
  context->save_for_backward({x_contiguous, weight_contiguous});
  context->saved_data[kStrideKey] = stride;
  context->saved_data[kPaddingKey] = padding;
  return CircularGather(x_contiguous, weight_contiguous, bias.contiguous(), stride, padding);
}

// The gradient of a gather along the ring links is a spread along the same links; the weight
// gradient correlates the output gradient with the input over them.
torch::autograd::variable_list CircularConv1dFunction::backward(
    torch::autograd::AutogradContext* context, torch::autograd::variable_list output_gradients) {
  const auto saved = context->get_saved_variables();
  const torch::Tensor& x = saved[0];
  const torch::Tensor& weight = saved[1];
  const std::int64_t stride = context->saved_data[kStrideKey].toInt();
  const std::int64_t padding = context->saved_data[kPaddingKey].toInt();
  const torch::Tensor gradient = output_gradients[0].contiguous();

  torch::Tensor x_gradient, weight_gradient, bias_gradient;
  if (context->needs_input_grad(0)) {
    x_gradient = CircularSpread(gradient, weight, torch::Tensor(), stride, padding);
  }
  if (context->needs_input_grad(1)) {
    weight_gradient = CircularWeightGradient(gradient, x, weight.size(2), stride, padding);
  }
  if (context->needs_input_grad(2)) bias_gradient = gradient.sum(at::IntArrayRef{0, 2});
  // No gradients for stride and padding.
  return {x_gradient, weight_gradient, bias_gradient, torch::Tensor(), torch::Tensor()};
}

CircularConv1dImpl::CircularConv1dImpl(CircularConv1dOptions options) : options_(options) {
  weight = register_parameter(
      "weight",
      torch::empty({options_.out_channels(), options_.in_channels(), options_.kernel_size()}));
  bias = register_parameter("bias", torch::empty({options_.out_channels()}));
  reset_parameters();
}

torch::Tensor CircularConv1dImpl::forward(const torch::Tensor& x) {
  return CircularConv1dFunction::apply(x, weight, bias, options_.stride(), options_.padding());
}

void CircularConv1dImpl::reset_parameters() { ResetConvolutionParameters(weight, bias); }

void CircularConv1dImpl::pretty_print(std::ostream& stream) const {
  stream << "colav::CircularConv1d(" << options_.in_channels() << ", " << options_.out_channels()
         << ", kernel_size=" << options_.kernel_size() << ", stride=" << options_.stride()
         << ", padding=" << options_.padding() << ")";
}

void ResetConvolutionParameters(torch::Tensor& weight, torch::Tensor& bias,
                                const c10::optional<torch::Generator>& generator) {
  torch::NoGradGuard no_grad;
  const std::int64_t fan_in = std::get<0>(torch::nn::init::_calculate_fan_in_and_fan_out(weight));
  // torch::nn::init::kaiming_uniform_(weight, a = sqrt(5)) step by step: it takes no generator.
  const double gain = torch::nn::init::calculate_gain(torch::kLeakyReLU, std::sqrt(5.0));
  const double weight_bound = std::sqrt(3.0) * (gain / std::sqrt(static_cast<double>(fan_in)));
  weight.uniform_(-weight_bound, weight_bound, generator);
  const double bias_bound = 1.0 / std::sqrt(static_cast<double>(fan_in));
  bias.uniform_(-bias_bound, bias_bound, generator);
}

void RedrawLayerParameters(torch::nn::Module& module, torch::Generator& generator) {
  for (const std::shared_ptr<torch::nn::Module>& layer : module.modules()) {
    torch::OrderedDict<std::string, torch::Tensor> parameters =
        layer->named_parameters(/*recurse=*/false);
    torch::Tensor* weight = parameters.find("weight");
    torch::Tensor* bias = parameters.find("bias");
    if (weight != nullptr && bias != nullptr) ResetConvolutionParameters(*weight, *bias, generator);
  }
}

}  // namespace colav

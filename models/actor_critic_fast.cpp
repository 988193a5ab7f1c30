#include "models/actor_critic_fast.h"

#include <algorithm>

#include "env/environment_spec.h"
#include "models/float_data.h"

namespace colav {
namespace {

std::vector<torch::Tensor> ZerosLike(const std::vector<torch::Tensor>& tensors) {
  std::vector<torch::Tensor> zeros;
  zeros.reserve(tensors.size());
  for (const torch::Tensor& tensor : tensors) zeros.push_back(torch::zeros_like(tensor));
  return zeros;
}

void Activate(FastLayer::Activation activation, float* x, int n) {
  if (activation == FastLayer::Activation::kTanh) kernels::TanhInPlace(x, n);
  if (activation == FastLayer::Activation::kRelu) kernels::ReluInPlace(x, n);
}

void ActivationBackward(FastLayer::Activation activation, float* grad, const float* y, int n) {
  if (activation == FastLayer::Activation::kTanh) kernels::TanhBackwardInPlace(grad, y, n);
  if (activation == FastLayer::Activation::kRelu) kernels::ReluBackwardInPlace(grad, y, n);
}

kernels::CircularConvShape ConvShape(const torch::nn::detail::ConvNdOptions<1>& options,
                                     int length) {
  TORCH_CHECK(c10::holds_alternative<torch::enumtype::kCircular>(options.padding_mode()) &&
                  (*options.dilation())[0] == 1 && options.groups() == 1,
              "FastActorCritic supports circular, undilated, ungrouped convolutions only");
  const auto& padding = c10::get<torch::ExpandingArray<1>>(options.padding());
  return {static_cast<int>(options.in_channels()),
          static_cast<int>(options.out_channels()),
          static_cast<int>((*options.kernel_size())[0]),
          static_cast<int>((*options.stride())[0]),
          static_cast<int>((*padding)[0]),
          length};
}

// Transposes `width` values from `offset` of `count` rows (row-major) into columns 0..count-1 of
// the feature-major [width, stride] array `out`.
void GatherRows(const float* const* rows, int count, int offset, int width, int stride,
                float* out) {
  for (int b = 0; b < count; ++b) {
    const float* row = rows[b] + offset;
    for (int i = 0; i < width; ++i) out[i * stride + b] = row[i];
  }
}

// Writes the states [H, B] (feature-major) into the first H values of the rows of the row-major
// [B, stride] array `rows`.
void ScatterStates(const float* states, int H, int B, int stride, float* rows) {
  for (int b = 0; b < B; ++b) {
    for (int j = 0; j < H; ++j) {
      rows[static_cast<std::ptrdiff_t>(b) * stride + j] = states[j * B + b];
    }
  }
}

// dst [inner, outer, block] = src [outer, inner, block] with its first two axes swapped: moves
// encodings between the perception stack's [P, scans, B] and the feature rows' [scans, P, B].
void SwapBlockAxes(const float* src, int outer, int inner, int block, float* dst) {
  for (int o = 0; o < outer; ++o) {
    for (int i = 0; i < inner; ++i) {
      const float* from = src + (static_cast<std::ptrdiff_t>(o) * inner + i) * block;
      std::copy(from, from + block, dst + (static_cast<std::ptrdiff_t>(i) * outer + o) * block);
    }
  }
}

}  // namespace

FastLayerStack::FastLayerStack(std::vector<FastLayer> layers, int max_batch)
    : layers_(std::move(layers)) {
  int widest = 0;
  for (const FastLayer& layer : layers_) {
    outputs_.emplace_back(static_cast<std::size_t>(layer.out_size) * max_batch);
    widest = std::max({widest, layer.in_size, layer.out_size});
  }
  gradient_a_.resize(static_cast<std::size_t>(widest) * max_batch);
  gradient_b_.resize(gradient_a_.size());
  transposed_.resize(gradient_a_.size());
}

const float* FastLayerStack::Forward(const float* input, int B) {
  const float* x = input;
  for (std::size_t i = 0; i < layers_.size(); ++i) {
    const FastLayer& layer = layers_[i];
    float* y = outputs_[i].data();
    if (layer.kind == FastLayer::Kind::kLinear) {
      kernels::LinearForward(FloatData(layer.weight), FloatData(layer.bias), x, layer.in_size,
                             layer.out_size, B, y);
    } else {
      kernels::CircularConvForward(layer.conv, FloatData(layer.weight), FloatData(layer.bias), x, B,
                                   y);
    }
    Activate(layer.activation, y, layer.out_size * B);
    x = y;
  }
  return x;
}

void FastLayerStack::Backward(const float* input, float* d_output, int B, float* d_input) {
  float* dy = d_output;
  for (std::size_t i = layers_.size(); i-- > 0;) {
    const FastLayer& layer = layers_[i];
    ActivationBackward(layer.activation, dy, outputs_[i].data(), layer.out_size * B);
    const float* x = i == 0 ? input : outputs_[i - 1].data();
    float* dx =
        i == 0 ? d_input : (dy == gradient_a_.data() ? gradient_b_.data() : gradient_a_.data());
    if (layer.kind == FastLayer::Kind::kLinear) {
      kernels::LinearBackward(FloatData(layer.weight), x, dy, layer.in_size, layer.out_size, B,
                              FloatData(layer.weight_grad), FloatData(layer.bias_grad), dx,
                              transposed_.data());
    } else {
      kernels::CircularConvBackward(layer.conv, FloatData(layer.weight), x, dy, B,
                                    FloatData(layer.weight_grad), FloatData(layer.bias_grad), dx);
    }
    dy = dx;
  }
}

FastActorCritic::FastActorCritic(ActorCritic model, int max_batch)
    : model_(std::move(model)),
      max_batch_(max_batch),
      features_dim_(static_cast<int>(model_->features_extractor()->features_dim())),
      scans_(static_cast<int>(model_->features_extractor()->options().scans)),
      observation_size_(static_cast<int>(model_->features_extractor()->observation_size())),
      critic_observation_size_(static_cast<int>(model_->options().critic_observation_size())),
      extractor_trainable_(model_->features_extractor()->trainable()),
      parameters_(model_->TrainableParameters()),
      gradients_(ZerosLike(parameters_)),
      log_std_(model_->log_std()),
      log_std_grad_(GradientOf(log_std_)),
      perception_([this] {
        std::vector<FastLayer> layers;
        int length = kNumRays;
        for (const PerceptionLayer& layer : model_->features_extractor()->layers()) {
          const auto activation =
              layer.relu ? FastLayer::Activation::kRelu : FastLayer::Activation::kNone;
          if (layer.linear) {
            layers.push_back(Bind(FastLayer::Kind::kLinear, layer.linear->weight,
                                  layer.linear->bias, activation));
            continue;
          }
          FastLayer conv =
              Bind(FastLayer::Kind::kConv, layer.conv->weight, layer.conv->bias, activation);
          conv.conv = ConvShape(layer.conv->options, length);
          conv.in_size = conv.conv.in_channels * length;
          length = conv.conv.out_length();
          conv.out_size = conv.conv.out_channels * length;
          layers.push_back(conv);
        }
        return FastLayerStack(std::move(layers), scans_ * max_batch_);
      }()),
      actor_([this] {
        std::vector<FastLayer> layers;
        for (const auto& module : model_->mlp_extractor()->policy_net->children()) {
          if (auto linear = std::dynamic_pointer_cast<torch::nn::LinearImpl>(module)) {
            layers.push_back(Bind(FastLayer::Kind::kLinear, linear->weight, linear->bias,
                                  FastLayer::Activation::kTanh));
          }
        }
        layers.push_back(Bind(FastLayer::Kind::kLinear, model_->action_net()->weight,
                              model_->action_net()->bias, FastLayer::Activation::kNone));
        return FastLayerStack(std::move(layers), max_batch_);
      }()),
      critic_([this] {
        std::vector<FastLayer> layers;
        for (const auto& module : model_->mlp_extractor()->value_net->children()) {
          if (auto linear = std::dynamic_pointer_cast<torch::nn::LinearImpl>(module)) {
            layers.push_back(Bind(FastLayer::Kind::kLinear, linear->weight, linear->bias,
                                  FastLayer::Activation::kTanh));
          }
        }
        layers.push_back(Bind(FastLayer::Kind::kLinear, model_->value_net()->weight,
                              model_->value_net()->bias, FastLayer::Activation::kNone));
        return FastLayerStack(std::move(layers), max_batch_);
      }()),
      rows_(max_batch),
      perception_input_(static_cast<std::size_t>(kNumRays) * scans_ * max_batch),
      features_(static_cast<std::size_t>(features_dim_) * max_batch),
      trunk_input_(recurrent_size() > 0 ? static_cast<std::size_t>(actor_.in_size()) * max_batch
                                        : 0),
      critic_trunk_input_(model_->critic_recurrent() || critic_observation_size_ > 0
                              ? static_cast<std::size_t>(critic_.in_size()) * max_batch
                              : 0),
      predict_critic_rows_(critic_observation_size_ > 0 ? max_batch : 0),
      d_features_actor_(static_cast<std::size_t>(actor_.in_size()) * max_batch),
      d_features_critic_(static_cast<std::size_t>(critic_.in_size()) * max_batch),
      d_perception_(
          scans_ > 1 ? static_cast<std::size_t>(features_dim_ - kNavigationSize) * max_batch : 0) {
  TORCH_CHECK(perception_.in_size() == kNumRays, "the perception stack must read 180 values");
  TORCH_CHECK(kNavigationSize + scans_ * perception_.out_size() == features_dim_,
              "perception output does not match features_dim");
  const auto bind_gru = [&](std::optional<FastGru>& gru, torch::nn::GRUCell& cell) {
    if (!cell) return;
    gru.emplace(cell,
                std::vector<torch::Tensor>{GradientOf(cell->weight_ih), GradientOf(cell->weight_hh),
                                           GradientOf(cell->bias_ih), GradientOf(cell->bias_hh)},
                max_batch);
  };
  bind_gru(gru_, model_->recurrent());
  bind_gru(critic_gru_, model_->critic_recurrent());
  if (gru_) {
    initial_states_columns_.resize(static_cast<std::size_t>(state_size()) * max_batch);
    state_rows_.resize(max_batch);
    d_gru_input_.resize(features_.size());
  }
}

torch::Tensor FastActorCritic::GradientOf(const torch::Tensor& parameter) const {
  for (std::size_t i = 0; i < parameters_.size(); ++i) {
    if (parameters_[i].is_same(parameter)) return gradients_[i];
  }
  return {};  // frozen
}

FastLayer FastActorCritic::Bind(FastLayer::Kind kind, const torch::Tensor& weight,
                                const torch::Tensor& bias, FastLayer::Activation activation) const {
  TORCH_CHECK(
      weight.is_contiguous() && weight.scalar_type() == torch::kFloat32 && weight.device().is_cpu(),
      "FastActorCritic needs contiguous float32 CPU parameters");
  FastLayer layer;
  layer.kind = kind;
  layer.activation = activation;
  layer.weight = weight;
  layer.bias = bias;
  layer.weight_grad = GradientOf(weight);
  layer.bias_grad = GradientOf(bias);
  if (kind == FastLayer::Kind::kLinear) {
    layer.in_size = static_cast<int>(weight.size(1));
    layer.out_size = static_cast<int>(weight.size(0));
  }
  return layer;
}

void FastActorCritic::Predict(const float* observations, int B, float* mean, float* value,
                              float* states, const float* critic_observations) {
  TORCH_CHECK(B <= max_batch_, "batch larger than FastActorCritic's max_batch");
  TORCH_CHECK((states != nullptr) == (gru_.has_value()),
              "a recurrent model predicts from states, a memoryless one without");
  TORCH_CHECK((critic_observations != nullptr) == (critic_observation_size_ > 0),
              "a privileged critic predicts from critic observations, another one without");
  for (int b = 0; b < B; ++b) {
    rows_[b] = observations + static_cast<std::ptrdiff_t>(b) * observation_size_;
    if (gru_) state_rows_[b] = states + static_cast<std::ptrdiff_t>(b) * state_size();
    if (critic_observations != nullptr) {
      predict_critic_rows_[b] =
          critic_observations + static_cast<std::ptrdiff_t>(b) * critic_observation_size_;
    }
  }
  if (gru_) SetSequences(state_rows_.data(), nullptr, B);  // B sequences of one step
  if (critic_observations != nullptr) SetCriticObservations(predict_critic_rows_.data());
  ForwardObservations(rows_.data(), B);
  for (int b = 0; b < B; ++b) {
    for (int j = 0; j < kActionSize; ++j) mean[b * kActionSize + j] = mean_[j * B + b];
    value[b] = value_[b];
  }
  const std::ptrdiff_t features = static_cast<std::ptrdiff_t>(features_dim_) * B;
  if (gru_) {
    ScatterStates(trunk_input_.data() + features, recurrent_size(), B, state_size(), states);
  }
  if (critic_gru_) {
    ScatterStates(critic_trunk_input_.data() + features, recurrent_size(), B, state_size(),
                  states + recurrent_size());
  }
}

void FastActorCritic::SetSequences(const float* const* initial_states, const std::uint8_t* reset,
                                   int sequences) {
  TORCH_CHECK(gru_, "SetSequences is for recurrent models");
  initial_states_ = initial_states;
  reset_ = reset;
  sequences_ = sequences;
}

void FastActorCritic::SetCriticObservations(const float* const* rows) {
  TORCH_CHECK(critic_observation_size_ > 0, "SetCriticObservations is for privileged critics");
  critic_rows_ = rows;
}

void FastActorCritic::Features(const float* observations, int count, float* features) {
  for (int start = 0; start < count; start += max_batch_) {
    const int B = std::min(max_batch_, count - start);
    for (int b = 0; b < B; ++b) {
      rows_[b] = observations + static_cast<std::ptrdiff_t>(start + b) * observation_size_;
    }
    ForwardExtractor(rows_.data(), B);
    kernels::Transpose(features_.data(), features_dim_, B,
                       features + static_cast<std::ptrdiff_t>(start) * features_dim_);
  }
}

void FastActorCritic::ForwardObservations(const float* const* rows, int B) {
  ForwardExtractor(rows, B);
  ForwardFromFeatures(B);
}

void FastActorCritic::ForwardFeatures(const float* const* rows, int B) {
  GatherRows(rows, B, 0, features_dim_, B, features_.data());
  ForwardFromFeatures(B);
}

// features_ [features_dim, B] of the observation rows: the navigation values, then the encodings
// of scans 0, 1, ... from one perception pass over all scans * B scans.
void FastActorCritic::ForwardExtractor(const float* const* rows, int B) {
  TORCH_CHECK(B <= max_batch_, "batch larger than FastActorCritic's max_batch");
  const int samples = scans_ * B;
  GatherRows(rows, B, 0, kNavigationSize, B, features_.data());
  for (int k = 0; k < scans_; ++k) {
    GatherRows(rows, B, kNavigationSize + k * kNumRays, kNumRays, samples,
               perception_input_.data() + k * B);
  }
  const float* perception = perception_.Forward(perception_input_.data(), samples);
  SwapBlockAxes(perception, perception_.out_size(), scans_, B,
                features_.data() + kNavigationSize * B);
}

void FastActorCritic::ForwardFromFeatures(int B) {
  TORCH_CHECK(B <= max_batch_, "batch larger than FastActorCritic's max_batch");
  if (gru_) ForwardRecurrent(B);
  if (critic_observation_size_ > 0) GatherCriticObservations(B);
  mean_ = actor_.Forward(TrunkInput(), B);
  value_ = critic_.Forward(CriticTrunkInput(), B);
}

// After the memory's forward: its own memory's rows are in critic_trunk_input_ already, the
// shared memory's in the actor's trunk input.
void FastActorCritic::GatherCriticObservations(int B) {
  TORCH_CHECK(critic_rows_ != nullptr, "a privileged critic needs SetCriticObservations first");
  const std::size_t read =
      static_cast<std::size_t>(critic_.in_size() - critic_observation_size_) * B;
  if (!critic_gru_) std::copy_n(TrunkInput(), read, critic_trunk_input_.data());
  GatherRows(critic_rows_, B, 0, critic_observation_size_, B, critic_trunk_input_.data() + read);
}

// The GRUs' states over the sequences of SetSequences, beside the features in the trunks' inputs.
void FastActorCritic::ForwardRecurrent(int B) {
  const int S = sequences_;
  TORCH_CHECK(S > 0 && B % S == 0, "the batch is not whole sequences (SetSequences)");
  const int state = state_size();
  for (int s = 0; s < S; ++s) {
    for (int j = 0; j < state; ++j) initial_states_columns_[j * S + s] = initial_states_[s][j];
  }
  ForwardMemory(*gru_, initial_states_columns_.data(), B, trunk_input_.data());
  if (critic_gru_) {
    ForwardMemory(*critic_gru_, initial_states_columns_.data() + recurrent_size() * S, B,
                  critic_trunk_input_.data());
  }
}

// trunk_input = [features_; the state `gru` reaches after each sample from `initial`].
void FastActorCritic::ForwardMemory(FastGru& gru, const float* initial, int B, float* trunk_input) {
  const int S = sequences_;
  const float* states = gru.ForwardSequences(features_.data(), initial, reset_, B / S, S);
  const std::size_t features = static_cast<std::size_t>(features_dim_) * B;
  std::copy_n(features_.data(), features, trunk_input);
  std::copy_n(states, static_cast<std::size_t>(recurrent_size()) * B, trunk_input + features);
}

// d_trunk [features_dim + H, B]: its state rows go back through `gru`, whose input gradient joins
// the feature rows of d_features.
void FastActorCritic::BackwardMemory(FastGru& gru, float* d_trunk, float* d_features, int B) {
  float* d_states = d_trunk + static_cast<std::ptrdiff_t>(features_dim_) * B;
  gru.BackwardSequences(features_.data(), d_states, d_gru_input_.data());
  const int n = features_dim_ * B;
  for (int i = 0; i < n; ++i) d_features[i] += d_gru_input_[i];
}

void FastActorCritic::Backward(float* d_mean, float* d_value, const float* d_log_std, int B) {
  const bool input_gradient = extractor_trainable_ || gru_.has_value();
  actor_.Backward(TrunkInput(), d_mean, B, input_gradient ? d_features_actor_.data() : nullptr);
  critic_.Backward(CriticTrunkInput(), d_value, B,
                   input_gradient ? d_features_critic_.data() : nullptr);
  std::copy(d_log_std, d_log_std + kActionSize, FloatData(log_std_grad_));
  if (!input_gradient) return;
  // Both heads read the features: their gradients add up; so do their state rows when both losses
  // train one memory.
  const bool critic_trains_actor_memory = model_->options().value_trains_memory && !critic_gru_;
  const int n = (critic_trains_actor_memory ? actor_.in_size() : features_dim_) * B;
  for (int i = 0; i < n; ++i) d_features_actor_[i] += d_features_critic_[i];
  if (gru_) BackwardMemory(*gru_, d_features_actor_.data(), d_features_actor_.data(), B);
  if (critic_gru_) {
    BackwardMemory(*critic_gru_, d_features_critic_.data(), d_features_actor_.data(), B);
  }
  if (!extractor_trainable_) return;
  float* d_encodings = d_features_actor_.data() + kNavigationSize * B;  // the perception's rows
  // The scans share the stack's weights: one backward over all scans * B samples sums their
  // gradients. A single scan's rows are already in the stack's layout.
  float* d_perception = d_encodings;
  if (scans_ > 1) {
    d_perception = d_perception_.data();
    SwapBlockAxes(d_encodings, scans_, perception_.out_size(), B, d_perception);
  }
  perception_.Backward(perception_input_.data(), d_perception, scans_ * B, nullptr);
}

}  // namespace colav

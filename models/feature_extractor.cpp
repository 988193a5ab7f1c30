#include "models/feature_extractor.h"

#include <ATen/CPUGeneratorImpl.h>
#include <fmt/format.h>

#include <sstream>
#include <stdexcept>
#include <utility>

#include "env/environment_spec.h"
#include "models/torchscript_export.h"
#include "src/error.h"

namespace colav {
namespace {

// Largest difference tolerated between the VAE's own mu and this extractor's copy of it.
constexpr double kEncoderCopyTolerance = 1e-5;
// Random closeness scans used to check that copy, drawn from their own fixed stream.
constexpr std::int64_t kEncoderCheckSamples = 16;
constexpr std::uint64_t kEncoderCheckSeed = 1;

std::int64_t ConvOutputLength(std::int64_t length, const ConvLayerSpec& layer) {
  return (length + 2 * layer.padding - layer.kernel_size) / layer.stride + 1;
}

VaeArchitecture ArchitectureOf(ExtractorKind kind) {
  return kind == ExtractorKind::kVaeDeep ? VaeArchitecture::kDeep : VaeArchitecture::kShallow;
}

}  // namespace

ExtractorKind ParseExtractorKind(const std::string& name) {
  if (name == "baseline") return ExtractorKind::kBaseline;
  if (name == "vae-shallow") return ExtractorKind::kVaeShallow;
  if (name == "vae-deep") return ExtractorKind::kVaeDeep;
  throw UserError("unknown feature extractor '" + name +
                  "' (expected baseline, vae-shallow or vae-deep)");
}

std::string ExtractorKindName(ExtractorKind kind) {
  switch (kind) {
    case ExtractorKind::kBaseline:
      return "baseline";
    case ExtractorKind::kVaeShallow:
      return "vae-shallow";
    case ExtractorKind::kVaeDeep:
      return "vae-deep";
  }
  throw std::logic_error("unknown ExtractorKind");
}

EncoderHead ParseEncoderHead(const std::string& name) {
  if (name == "mu") return EncoderHead::kMu;
  if (name == "reference") return EncoderHead::kReference;
  throw UserError("unknown encoder head '" + name + "' (expected mu or reference)");
}

std::string EncoderHeadName(EncoderHead head) {
  return head == EncoderHead::kReference ? "reference" : "mu";
}

std::vector<ConvLayerSpec> ParseConvStack(const std::string& spec) {
  const auto bad = [&spec](const std::string& why) {
    return UserError("bad conv stack '" + spec + "': " + why +
                     " (expected out:kernel:stride:padding[,...])");
  };
  if (spec.empty() || spec.back() == ',') throw bad("missing layer");
  std::vector<ConvLayerSpec> layers;
  std::stringstream layer_specs(spec);
  std::string layer_spec;
  std::int64_t in_channels = 1;
  std::int64_t length = kNumRays;
  while (std::getline(layer_specs, layer_spec, ',')) {
    std::stringstream fields(layer_spec);
    std::int64_t values[4];
    char separator = ':';
    for (int i = 0; i < 4; ++i) {
      if ((i > 0 && !(fields >> separator)) || separator != ':' || !(fields >> values[i]) ||
          values[i] < (i == 3 ? 0 : 1)) {
        throw bad("layer '" + layer_spec + "'");
      }
    }
    if (fields >> separator) throw bad("layer '" + layer_spec + "'");
    const ConvLayerSpec layer{in_channels, values[0], values[1], values[2], values[3]};
    if (layer.padding > length || length + 2 * layer.padding < layer.kernel_size) {
      throw bad("layer '" + layer_spec + "' does not fit an input of length " +
                std::to_string(length));
    }
    length = ConvOutputLength(length, layer);
    in_channels = layer.out_channels;
    layers.push_back(layer);
  }
  if (layers.empty()) throw bad("no layer");
  return layers;
}

std::string ConvStackText(const std::vector<ConvLayerSpec>& layers) {
  std::string text;
  for (const ConvLayerSpec& layer : layers) {
    text += fmt::format("{}{}:{}:{}:{}", text.empty() ? "" : ",", layer.out_channels,
                        layer.kernel_size, layer.stride, layer.padding);
  }
  return text;
}

FeatureExtractorImpl::FeatureExtractorImpl(FeatureExtractorOptions options)
    : options_(std::move(options)) {
  TORCH_CHECK(options_.scans >= 1, "a feature extractor needs at least one scan, got ",
              options_.scans);
  perception_ = register_module("perception", torch::nn::ModuleList());
  if (options_.kind == ExtractorKind::kBaseline) {
    BuildConvs(options_.baseline_convs);
    return;
  }
  BuildConvs(EncoderConvLayers(ArchitectureOf(options_.kind)));
  PerceptionLayer head;
  head.linear = torch::nn::Linear(perception_dims_, options_.latent_dims);
  head.relu = options_.head == EncoderHead::kReference;
  perception_->push_back(head.linear);
  layers_.push_back(head);
  perception_dims_ = options_.latent_dims;
  if (!options_.encoder.empty()) LoadPretrainedEncoder();
  if (options_.locked) {
    for (torch::Tensor& parameter : perception_->parameters()) parameter.requires_grad_(false);
  }
}

void FeatureExtractorImpl::BuildConvs(const std::vector<ConvLayerSpec>& convs) {
  std::int64_t length = kNumRays;
  for (std::size_t i = 0; i < convs.size(); ++i) {
    const ConvLayerSpec& spec = convs[i];
    PerceptionLayer layer;
    layer.conv = torch::nn::Conv1d(
        torch::nn::Conv1dOptions(spec.in_channels, spec.out_channels, spec.kernel_size)
            .stride(spec.stride)
            .padding(spec.padding)
            .padding_mode(torch::kCircular));
    layer.relu = i + 1 < convs.size();
    perception_->push_back(layer.conv);
    layers_.push_back(layer);
    length = ConvOutputLength(length, spec);
  }
  perception_dims_ = convs.back().out_channels * length;
}

void FeatureExtractorImpl::LoadPretrainedEncoder() {
  const std::string file = "encoder file '" + options_.encoder.string() + "'";
  VaeEncoder encoder = LoadVaeEncoder(options_.encoder);
  if (encoder->options().architecture != ArchitectureOf(options_.kind)) {
    throw UserError(file + " holds a " + VaeArchitectureName(encoder->options().architecture) +
                    " encoder, but the extractor is " + ExtractorKindName(options_.kind));
  }
  if (encoder->options().latent_dims != options_.latent_dims) {
    throw UserError(file + " has latent size " + std::to_string(encoder->options().latent_dims) +
                    ", expected " + std::to_string(options_.latent_dims) +
                    " (set extractor.latent_dims to use it)");
  }
  // The VAE's parameters are its conv stack in order, then fc_mu, then fc_logvar (unused here).
  torch::NoGradGuard no_grad;
  const std::vector<torch::Tensor> source = encoder->parameters();
  const std::vector<torch::Tensor> target = perception_->parameters();
  TORCH_CHECK(source.size() == target.size() + 2, "unexpected VaeEncoder parameter list");
  for (std::size_t i = 0; i < target.size(); ++i) target[i].copy_(source[i]);

  // The copy relies on the VAE's layer order; check that it computes the VAE's mu.
  const torch::Tensor scans =
      torch::rand({kEncoderCheckSamples, kNumRays},
                  at::make_generator<at::CPUGeneratorImpl>(kEncoderCheckSeed));
  const torch::Tensor mu = encoder->Mu(scans);
  const torch::Tensor expected = layers_.back().relu ? torch::relu(mu) : mu;
  const double difference = (Perception(scans) - expected).abs().max().item<double>();
  if (!(difference < kEncoderCopyTolerance)) {
    throw std::logic_error("feature extractor does not reproduce the mu of " + file);
  }
}

torch::Tensor FeatureExtractorImpl::Perception(const torch::Tensor& closeness) {
  torch::Tensor h = closeness.unsqueeze(1);
  for (PerceptionLayer& layer : layers_) {
    h = layer.conv ? layer.conv->forward(h) : layer.linear->forward(h.flatten(1));
    if (layer.relu) h = torch::relu(h);
  }
  return h.flatten(1);
}

torch::Tensor FeatureExtractorImpl::forward(const torch::Tensor& observations) {
  TORCH_CHECK(observations.dim() == 2 && observations.size(1) == observation_size(),
              "observations must be [B, ", observation_size(), "] (", kNavigationSize,
              " navigation values, then ", options_.scans, " scans of ", kNumRays, "), got ",
              observations.sizes());
  // One batch of B * scans single scans through the shared stack (views for a single scan).
  const std::int64_t batch = observations.size(0);
  const torch::Tensor scans = observations.narrow(1, kNavigationSize, kNumRays * options_.scans)
                                  .reshape({batch * options_.scans, kNumRays});
  return torch::cat({observations.narrow(1, 0, kNavigationSize),
                     Perception(scans).reshape({batch, options_.scans * perception_dims_})},
                    1);
}

std::int64_t FeatureExtractorImpl::features_dim() const {
  return kNavigationSize + options_.scans * perception_dims_;
}

std::int64_t FeatureExtractorImpl::observation_size() const {
  return kNavigationSize + options_.scans * kNumRays;
}

bool FeatureExtractorImpl::trainable() const {
  return options_.kind == ExtractorKind::kBaseline || !options_.locked;
}

}  // namespace colav

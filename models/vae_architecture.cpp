#include "models/vae_architecture.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "src/error.h"

namespace colav {

VaeArchitecture ParseVaeArchitecture(const std::string& name) {
  if (name == "shallow") return VaeArchitecture::kShallow;
  if (name == "deep") return VaeArchitecture::kDeep;
  throw UserError("unknown VAE architecture '" + name + "' (expected shallow or deep)");
}

std::string VaeArchitectureName(VaeArchitecture architecture) {
  return architecture == VaeArchitecture::kShallow ? "shallow" : "deep";
}

std::vector<ConvLayerSpec> EncoderConvLayers(VaeArchitecture architecture) {
  // The first layer sees 45 rays (90 degrees) every 15 rays: 180 -> 12 (spec reference-learning
  // 1.1); the deep model's 3-wide layers then mix neighbouring features.
  switch (architecture) {
    case VaeArchitecture::kShallow:
      return {{1, 1, 45, 15, 15}};
    case VaeArchitecture::kDeep:
      return {{1, 3, 45, 15, 15}, {3, 2, 3, 1, 1}, {2, 1, 3, 1, 1}};
  }
  throw std::logic_error("unknown VaeArchitecture");
}

std::vector<ConvLayerSpec> DecoderConvLayers(VaeArchitecture architecture) {
  std::vector<ConvLayerSpec> layers = EncoderConvLayers(architecture);
  std::reverse(layers.begin(), layers.end());
  for (ConvLayerSpec& layer : layers) std::swap(layer.in_channels, layer.out_channels);
  return layers;
}

}  // namespace colav

#include "train/vae/data.h"

#include <ATen/CPUGeneratorImpl.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "env/range_finder.h"
#include "src/error.h"
#include "train/dataset/file.h"

namespace colav {
namespace {

// The rows of one split, transformed, as a [n, 180] tensor.
torch::Tensor SplitTensor(const ScanDataset& dataset, DatasetSplit split,
                          ClosenessTransform transform) {
  std::vector<float> values;
  for (std::size_t row = 0; row < dataset.rows(); ++row) {
    if (dataset.split[row] != static_cast<std::int64_t>(split)) continue;
    const float* ranges = dataset.ranges.data() + row * kNumRays;
    for (int i = 0; i < kNumRays; ++i) {
      values.push_back(static_cast<float>(Closeness(ranges[i], transform)));
    }
  }
  const auto rows = static_cast<std::int64_t>(values.size() / kNumRays);
  return torch::from_blob(values.data(), {rows, kNumRays}, torch::kFloat32).clone();
}

torch::Tensor TestGroups(const ScanDataset& dataset) {
  std::vector<std::int64_t> groups;
  for (std::size_t row = 0; row < dataset.rows(); ++row) {
    if (dataset.split[row] == static_cast<std::int64_t>(DatasetSplit::kTest)) {
      groups.push_back(dataset.group[row]);
    }
  }
  return torch::tensor(groups, torch::kInt64);
}

}  // namespace

VaeData LoadVaeData(const std::filesystem::path& path, ClosenessTransform transform) {
  const ScanDataset dataset = ReadScanDataset(path);
  VaeData data;
  data.train = SplitTensor(dataset, DatasetSplit::kTrain, transform);
  data.validation = SplitTensor(dataset, DatasetSplit::kValidation, transform);
  data.test = SplitTensor(dataset, DatasetSplit::kTest, transform);
  data.test_group = TestGroups(dataset);
  const std::array<std::pair<const char*, const torch::Tensor*>, 3> splits = {
      {{"train", &data.train}, {"validation", &data.validation}, {"test", &data.test}}};
  for (const auto& [name, tensor] : splits) {
    if (tensor->size(0) == 0) {
      throw UserError(path.string() + ": the " + name + " split has no rows");
    }
  }
  return data;
}

torch::Tensor WithTrainingNoise(const torch::Tensor& x, double variance, std::uint64_t seed,
                                bool clip) {
  if (variance <= 0.0) return x.clone();
  torch::Generator generator = at::make_generator<at::CPUGeneratorImpl>(seed);
  torch::Tensor noisy = x + std::sqrt(variance) * torch::randn(x.sizes(), generator, x.options());
  if (clip) noisy.clamp_(0.0, 1.0);
  return noisy;
}

}  // namespace colav

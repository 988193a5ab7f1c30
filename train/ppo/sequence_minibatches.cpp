#include "train/ppo/sequence_minibatches.h"

#include <algorithm>

namespace colav {

std::vector<std::int64_t> SequenceMinibatchOrder(int num_steps, int num_envs, int L, int batch_size,
                                                 torch::Generator& generator) {
  const int per_world = num_steps / L;
  const int count = per_world * num_envs;
  const int per_minibatch = batch_size / L;
  const torch::Tensor permutation = torch::randperm(count, generator, torch::kLong);
  const std::int64_t* sequences = permutation.data_ptr<std::int64_t>();
  std::vector<std::int64_t> order;
  order.reserve(static_cast<std::size_t>(num_steps) * num_envs);
  for (int first = 0; first < count; first += per_minibatch) {
    const int S = std::min(per_minibatch, count - first);
    for (int t = 0; t < L; ++t) {
      for (int s = 0; s < S; ++s) {
        const std::int64_t sequence = sequences[first + s];
        const std::int64_t world = sequence / per_world;
        const std::int64_t step = (sequence % per_world) * L + t;
        order.push_back(step * num_envs + world);
      }
    }
  }
  return order;
}

void EpisodeStartsInSequences(const RolloutBuffer& buffer, const std::int64_t* indices, int B,
                              int L, std::vector<std::uint8_t>& starts) {
  const int S = B / L;
  starts.assign(B, 0);
  for (int b = S; b < B; ++b) starts[b] = buffer.dones()[indices[b] - buffer.num_envs()];
}

}  // namespace colav

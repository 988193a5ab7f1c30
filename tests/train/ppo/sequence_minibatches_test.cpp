#include "train/ppo/sequence_minibatches.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace colav {
namespace {

// 8 steps x 3 worlds in sequences of 4 steps, minibatches of 8 samples (2 sequences): 6
// sequences, every sample once, each minibatch two whole sequences in time-major order.
TEST(SequenceMinibatchesTest, WholeShuffledSequencesInTimeMajorOrder) {
  constexpr int kSteps = 8, kWorlds = 3, kLength = 4, kBatch = 8;
  auto generator = at::make_generator<at::CPUGeneratorImpl>(3);
  const std::vector<std::int64_t> order =
      SequenceMinibatchOrder(kSteps, kWorlds, kLength, kBatch, generator);
  std::vector<std::int64_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::int64_t> every(kSteps * kWorlds);
  std::iota(every.begin(), every.end(), 0);
  EXPECT_EQ(sorted, every);
  constexpr int S = kBatch / kLength;
  for (int start = 0; start < kSteps * kWorlds; start += kBatch) {
    for (int s = 0; s < S; ++s) {
      const std::int64_t first = order[start + s];
      EXPECT_EQ(first / kWorlds % kLength, 0) << "a sequence starts at a multiple of its length";
      for (int t = 1; t < kLength; ++t) {  // the same world, one step later each time
        EXPECT_EQ(order[start + t * S + s], first + t * kWorlds);
      }
    }
  }
  auto same_seed = at::make_generator<at::CPUGeneratorImpl>(3);
  auto other_seed = at::make_generator<at::CPUGeneratorImpl>(4);
  EXPECT_EQ(SequenceMinibatchOrder(kSteps, kWorlds, kLength, kBatch, same_seed), order);
  EXPECT_NE(SequenceMinibatchOrder(kSteps, kWorlds, kLength, kBatch, other_seed), order);
}

// Two sequences by hand: world 0's steps 0-3 and world 2's steps 4-7 (samples t * 3 + e).
// Episodes end at world 0's step 1, world 2's steps 3 and 5: they restart the state at world 0's
// step 2 and world 2's step 6; world 2's step 4 starts the sequence from its recorded state.
TEST(SequenceMinibatchesTest, EpisodeStartsInsideTheSequencesOnly) {
  RolloutBuffer buffer(8, 3, 1);
  buffer.dones(1)[0] = 1;
  buffer.dones(3)[2] = 1;
  buffer.dones(5)[2] = 1;
  const std::vector<std::int64_t> indices = {0, 14, 3, 17, 6, 20, 9, 23};
  std::vector<std::uint8_t> starts;
  EpisodeStartsInSequences(buffer, indices.data(), 8, 4, starts);
  EXPECT_EQ(starts, (std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 0, 0}));
}

}  // namespace
}  // namespace colav

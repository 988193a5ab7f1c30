// A recurrent policy's minibatches (SB3-contrib's RecurrentPPO and CleanRL's LSTM PPO train on
// consecutive steps too): the rollout cut into sequences of L consecutive steps of one world,
// shuffled, and laid out minibatch by minibatch in time-major order, so that sample t * S + s of a
// minibatch of S sequences is step t of its sequence s. Each sequence starts from the state the
// rollout recorded before its first step; an episode that starts inside it restarts the state.
#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <vector>

#include "train/ppo/rollout_buffer.h"

namespace colav {

/// The samples of a rollout of num_steps x num_envs (sample t * num_envs + e), every one exactly
/// once, in minibatches of batch_size samples (batch_size / L sequences; the last may have fewer),
/// the sequences shuffled by one randperm of `generator`. L must divide num_steps and batch_size.
std::vector<std::int64_t> SequenceMinibatchOrder(int num_steps, int num_envs, int L, int batch_size,
                                                 torch::Generator& generator);

/// For the minibatch of B samples `indices` (a stretch of SequenceMinibatchOrder of whole
/// sequences of L steps): per sample, whether an episode starts there after the sequence's first
/// step (its world's previous step ended an episode). The first steps get 0: their recorded state
/// is already 0 at an episode's start.
void EpisodeStartsInSequences(const RolloutBuffer& buffer, const std::int64_t* indices, int B,
                              int L, std::vector<std::uint8_t>& starts);

}  // namespace colav

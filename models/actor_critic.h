// The PPO agent's actor-critic (Stable-Baselines3 ActorCriticPolicy with the paper's net_arch,
// reference-learning 6.3): one feature extractor shared by actor and critic, then separate Tanh
// MLPs (default [128, 64, 32]); the actor's Linear head gives the mean of a diagonal Gaussian with
// a state-independent log std (init 0), the critic's gives the state value. The environment gets
// the Gaussian's sample clipped to [-1, 1] (SB3's default), or, with squash_actions, its tanh
// (SB3's squash_output, SAC's distribution); the deterministic action is the mean treated alike.
//
// Initialisation (SB3 ortho_init): trunks orthogonal with gain sqrt(2), action head 0.01, value
// head 1, biases 0. Unlike the reference (reference-learning 6.2), the pre-trained encoder keeps
// its weights; the baseline's conv keeps PyTorch's default initialisation. Every random draw comes
// from a generator seeded by ActorCriticOptions::seed.
//
// With recurrent_size H > 0 the policy has a memory: a GRU cell (torch.nn.GRUCell) between the
// extractor and the trunks, shared by actor and critic, turns the features x_t and the state
// h_{t-1} into h_t, and both trunks read [x_t, h_t] (the features stay in view, so the memory
// adds to the memoryless policy rather than replacing its input). The state is 0 at the start of
// every episode. With value_trains_memory false the critic reads it detached. With
// separate_critic_memory the critic has a GRU of its own (SB3-contrib's RecurrentPPO default), the
// actor's GRU only the actor's loss trains, and a step's state is [actor's state, critic's state].
// Their weights are orthogonal (gain 1, CleanRL's recurrent PPO), their biases 0.
//
// With critic_vessels K > 0 the critic is privileged (asymmetric actor-critic): its trunk reads
// [features, the true state of the K nearest moving vessels] (env/critic_observation.h), which
// only training computes; the actor reads the features alone. With a memory the critic's trunk
// reads [features, the state it reads, the vessels].
//
// Parameter names follow SB3's state dict: features_extractor.*, mlp_extractor.policy_net.{0,2,4},
// mlp_extractor.value_net.{0,2,4}, action_net, value_net, log_std; the GRU's are
// recurrent.{weight_ih, weight_hh, bias_ih, bias_hh} (gates in PyTorch's order r, z, n), the
// critic's own critic_recurrent.*.
#pragma once

#include <torch/torch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "env/critic_observation.h"
#include "env/environment_spec.h"
#include "models/feature_extractor.h"

namespace colav {

struct ActorCriticOptions {
  FeatureExtractorOptions extractor;
  std::vector<std::int64_t> hidden_sizes = {128, 64, 32};
  double log_std_init = 0.0;
  /// Actions tanh(u) of u ~ N(mean, std) instead of clip(u, -1, 1): the action distribution stays
  /// inside [-1, 1], so its entropy is bounded and the entropy bonus cannot widen the std without
  /// end (train/ppo/loss.h).
  bool squash_actions = false;
  /// Per action (thrust, yaw moment): 0 acts deterministically with the clipped mean (SB3's); a
  /// scale c > 0 with E[clip(u, -1, 1)], u ~ N(mean, (c * std)^2), the mean action of the training
  /// policy at that fraction of its std (a policy whose std far exceeds the box otherwise acts
  /// bang-bang, its clipped mean at a limit). Only the exported policy acts so; training is the
  /// same. Not with squash_actions.
  std::array<double, kActionSize> deterministic_std_scale{};
  /// Size of the GRU state between the extractor and the trunks; 0: no memory (the paper's).
  std::int64_t recurrent_size = 0;
  /// Whether the critic's loss trains the GRU as the actor's does (CleanRL's recurrent PPO). false:
  /// the critic still reads the state, detached, and only the actor's loss trains the memory
  /// (SB3-contrib's RecurrentPPO with a shared LSTM), so it keeps what steering needs.
  bool value_trains_memory = true;
  /// Whether the critic reads a GRU of its own (SB3-contrib's RecurrentPPO default) instead of the
  /// actor's; each trains on its own loss. Needs recurrent_size > 0 and value_trains_memory.
  bool separate_critic_memory = false;
  /// A privileged critic (asymmetric actor-critic): its trunk also reads the true motion of this
  /// many nearest moving vessels (env/critic_observation.h), which only training computes. The
  /// actor, and so the exported policy, sees the observation alone; the exported file has no
  /// value(obs) (nor step_value). 0: the critic reads what the actor reads (the paper's).
  int critic_vessels = 0;
  std::uint64_t seed = 0;  ///< seeds the initialisation

  /// Whether the deterministic action of some action is the expected clipped one.
  bool smooths_deterministic_action() const {
    return deterministic_std_scale[0] > 0 || deterministic_std_scale[1] > 0;
  }
  /// Values of a step's state: recurrent_size, twice that with separate_critic_memory.
  std::int64_t state_size() const { return recurrent_size * (separate_critic_memory ? 2 : 1); }
  /// Values of a sample's critic observation (critic_vessels' rows).
  std::int64_t critic_observation_size() const { return CriticObservationSize(critic_vessels); }
};

/// The two separate trunks (SB3's MlpExtractor); the critic's reads critic_inputs more values.
class MlpExtractorImpl : public torch::nn::Module {
 public:
  MlpExtractorImpl(std::int64_t features_dim, const std::vector<std::int64_t>& hidden_sizes,
                   std::int64_t critic_inputs = 0);

  torch::nn::Sequential policy_net{nullptr};  ///< Linear, Tanh, Linear, Tanh, ...
  torch::nn::Sequential value_net{nullptr};
};
TORCH_MODULE(MlpExtractor);

class ActorCriticImpl : public torch::nn::Module {
 public:
  explicit ActorCriticImpl(ActorCriticOptions options);

  /// observations [B, 6 + 180 * scans] (FeatureExtractorImpl::observation_size()) ->
  /// (action mean [B, 2], value [B, 1]). A privileged critic also reads critic_observations
  /// [B, critic_observation_size()].
  std::pair<torch::Tensor, torch::Tensor> forward(const torch::Tensor& observations,
                                                  const torch::Tensor& critic_observations = {});

  /// One step of a recurrent policy: observations [B, n] and states [B, state_size] (the state
  /// before these observations; 0 at an episode's start) -> (action mean [B, 2], value [B, 1],
  /// state after [B, state_size]). A privileged critic also reads critic_observations as forward.
  std::tuple<torch::Tensor, torch::Tensor, torch::Tensor> forward_recurrent(
      const torch::Tensor& observations, const torch::Tensor& states,
      const torch::Tensor& critic_observations = {});

  /// The parameters the optimiser updates: all but those of a locked encoder, in module order.
  std::vector<torch::Tensor> TrainableParameters() const;
  /// The parameters only the critic reads: its trunk, its value head and its own memory (if
  /// any). Everything else shapes the actions.
  std::vector<torch::Tensor> CriticParameters() const;

  const ActorCriticOptions& options() const { return options_; }
  FeatureExtractor& features_extractor() { return features_extractor_; }
  MlpExtractor& mlp_extractor() { return mlp_extractor_; }
  torch::nn::Linear& action_net() { return action_net_; }
  torch::nn::Linear& value_net() { return value_net_; }
  torch::Tensor& log_std() { return log_std_; }
  /// The GRU cell the actor reads (and the critic, unless separate_critic_memory); empty unless
  /// recurrent_size > 0.
  torch::nn::GRUCell& recurrent() { return recurrent_; }
  /// The critic's own GRU cell; empty unless separate_critic_memory.
  torch::nn::GRUCell& critic_recurrent() { return critic_recurrent_; }

 private:
  void Initialise();
  torch::Tensor PrivilegedCriticInput(const torch::Tensor& input,
                                      const torch::Tensor& critic_observations) const;

  ActorCriticOptions options_;
  FeatureExtractor features_extractor_{nullptr};
  torch::nn::GRUCell recurrent_{nullptr};
  torch::nn::GRUCell critic_recurrent_{nullptr};
  MlpExtractor mlp_extractor_{nullptr};
  torch::nn::Linear action_net_{nullptr};
  torch::nn::Linear value_net_{nullptr};
  torch::Tensor log_std_;
};
TORCH_MODULE(ActorCritic);

/// The action the environment gets for a Gaussian sample or mean `u` of one action dimension.
inline float BoundedAction(float u, bool squash_actions) {
  return squash_actions ? std::tanh(u) : std::clamp(u, -1.0f, 1.0f);
}

/// Fills `weight` (rows = dim 0) with a random orthogonal matrix times `gain`, drawn from
/// `generator` (torch.nn.init.orthogonal_'s algorithm).
void OrthogonalInit(const torch::Tensor& weight, double gain, torch::Generator& generator);

}  // namespace colav

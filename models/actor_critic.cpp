#include "models/actor_critic.h"

#include <cmath>

#include "env/environment_spec.h"
#include "models/circular_conv.h"

namespace colav {
namespace {

// SB3 ortho_init gains: hidden layers, action head, value head.
const double kTrunkGain = std::sqrt(2.0);
constexpr double kActionGain = 0.01;
constexpr double kValueGain = 1.0;
constexpr double kRecurrentGain = 1.0;  // CleanRL's ppo_atari_lstm

torch::nn::Sequential TanhMlp(std::int64_t in_features, const std::vector<std::int64_t>& sizes) {
  torch::nn::Sequential mlp;
  for (const std::int64_t size : sizes) {
    mlp->push_back(torch::nn::Linear(in_features, size));
    mlp->push_back(torch::nn::Tanh());
    in_features = size;
  }
  return mlp;
}

void InitLinear(torch::nn::Linear& linear, double gain, torch::Generator& generator) {
  OrthogonalInit(linear->weight, gain, generator);
  linear->bias.zero_();
}

void InitTrunk(torch::nn::Sequential& mlp, torch::Generator& generator) {
  for (auto& module : mlp->children()) {
    if (auto linear = std::dynamic_pointer_cast<torch::nn::LinearImpl>(module)) {
      torch::nn::Linear holder(linear);
      InitLinear(holder, kTrunkGain, generator);
    }
  }
}

}  // namespace

void OrthogonalInit(const torch::Tensor& weight, double gain, torch::Generator& generator) {
  torch::NoGradGuard no_grad;
  const std::int64_t rows = weight.size(0);
  const std::int64_t columns = weight.numel() / rows;
  torch::Tensor flat = torch::randn({rows, columns}, generator);
  if (rows < columns) flat = flat.t();
  auto [q, r] = torch::linalg_qr(flat);
  q = q * torch::diagonal(r).sign();  // makes the decomposition unique (uniform over O(n))
  if (rows < columns) q = q.t();
  weight.copy_(q.reshape(weight.sizes()) * gain);
}

MlpExtractorImpl::MlpExtractorImpl(std::int64_t features_dim,
                                   const std::vector<std::int64_t>& hidden_sizes,
                                   std::int64_t critic_inputs) {
  policy_net = register_module("policy_net", TanhMlp(features_dim, hidden_sizes));
  value_net = register_module("value_net", TanhMlp(features_dim + critic_inputs, hidden_sizes));
}

ActorCriticImpl::ActorCriticImpl(ActorCriticOptions options) : options_(std::move(options)) {
  TORCH_CHECK(!options_.hidden_sizes.empty(), "the actor and critic need a hidden layer");
  features_extractor_ = register_module("features_extractor", FeatureExtractor(options_.extractor));
  const std::int64_t features_dim = features_extractor_->features_dim();
  TORCH_CHECK(options_.recurrent_size >= 0, "recurrent_size must not be negative");
  TORCH_CHECK(!options_.separate_critic_memory ||
                  (options_.recurrent_size > 0 && options_.value_trains_memory),
              "a separate critic memory needs recurrent_size > 0 and value_trains_memory");
  TORCH_CHECK(options_.critic_vessels >= 0, "critic_vessels must not be negative");
  if (options_.recurrent_size > 0) {
    recurrent_ =
        register_module("recurrent", torch::nn::GRUCell(features_dim, options_.recurrent_size));
  }
  if (options_.separate_critic_memory) {
    critic_recurrent_ = register_module("critic_recurrent",
                                        torch::nn::GRUCell(features_dim, options_.recurrent_size));
  }
  mlp_extractor_ = register_module(
      "mlp_extractor", MlpExtractor(features_dim + options_.recurrent_size, options_.hidden_sizes,
                                    options_.critic_observation_size()));
  const std::int64_t latent = options_.hidden_sizes.back();
  action_net_ = register_module("action_net", torch::nn::Linear(latent, kActionSize));
  value_net_ = register_module("value_net", torch::nn::Linear(latent, 1));
  log_std_ = register_parameter("log_std", torch::full({kActionSize}, options_.log_std_init));
  Initialise();
}

void ActorCriticImpl::Initialise() {
  torch::NoGradGuard no_grad;
  auto generator = at::make_generator<at::CPUGeneratorImpl>(options_.seed);
  if (options_.extractor.kind == ExtractorKind::kBaseline) {
    for (const PerceptionLayer& layer : features_extractor_->layers()) {
      // PyTorch's default Conv1d initialisation, drawn from `generator`.
      torch::nn::Conv1d conv = layer.conv;
      ResetConvolutionParameters(conv->weight, conv->bias, generator);
    }
  }
  if (options_.extractor.kind != ExtractorKind::kBaseline &&
      options_.extractor.head == EncoderHead::kReference) {
    // SB3 initialises the extractor's Linear layers after loading the pre-trained weights.
    torch::nn::Linear head = features_extractor_->layers().back().linear;
    InitLinear(head, kTrunkGain, generator);
  }
  InitTrunk(mlp_extractor_->policy_net, generator);
  InitTrunk(mlp_extractor_->value_net, generator);
  InitLinear(action_net_, kActionGain, generator);
  InitLinear(value_net_, kValueGain, generator);
  // Last: the memoryless models draw exactly what they drew before, the shared memory too.
  for (torch::nn::GRUCell* cell : {&recurrent_, &critic_recurrent_}) {
    if (!*cell) continue;
    OrthogonalInit((*cell)->weight_ih, kRecurrentGain, generator);
    OrthogonalInit((*cell)->weight_hh, kRecurrentGain, generator);
    (*cell)->bias_ih.zero_();
    (*cell)->bias_hh.zero_();
  }
}

// The critic's trunk input: `input` followed, for a privileged critic, by its observations.
torch::Tensor ActorCriticImpl::PrivilegedCriticInput(
    const torch::Tensor& input, const torch::Tensor& critic_observations) const {
  const std::int64_t privileged = options_.critic_observation_size();
  TORCH_CHECK(privileged == 0 ? !critic_observations.defined()
                              : critic_observations.defined() && critic_observations.dim() == 2 &&
                                    critic_observations.size(1) == privileged,
              "the critic observations must match critic_vessels");
  return privileged == 0 ? input : torch::cat({input, critic_observations}, 1);
}

std::pair<torch::Tensor, torch::Tensor> ActorCriticImpl::forward(
    const torch::Tensor& observations, const torch::Tensor& critic_observations) {
  TORCH_CHECK(!recurrent_, "a recurrent model steps with forward_recurrent");
  const torch::Tensor features = features_extractor_->forward(observations);
  const torch::Tensor critic_input = PrivilegedCriticInput(features, critic_observations);
  return {action_net_->forward(mlp_extractor_->policy_net->forward(features)),
          value_net_->forward(mlp_extractor_->value_net->forward(critic_input))};
}

std::tuple<torch::Tensor, torch::Tensor, torch::Tensor> ActorCriticImpl::forward_recurrent(
    const torch::Tensor& observations, const torch::Tensor& states,
    const torch::Tensor& critic_observations) {
  TORCH_CHECK(recurrent_, "forward_recurrent needs a model with recurrent_size > 0");
  const torch::Tensor features = features_extractor_->forward(observations);
  const std::int64_t H = options_.recurrent_size;
  const torch::Tensor actor_state = recurrent_->forward(features, states.narrow(1, 0, H));
  const torch::Tensor actor_input = torch::cat({features, actor_state}, 1);
  torch::Tensor critic_input = actor_input;
  torch::Tensor next_states = actor_state;
  if (critic_recurrent_) {
    const torch::Tensor critic_state = critic_recurrent_->forward(features, states.narrow(1, H, H));
    critic_input = torch::cat({features, critic_state}, 1);
    next_states = torch::cat({actor_state, critic_state}, 1);
  } else if (!options_.value_trains_memory) {
    critic_input = torch::cat({features, actor_state.detach()}, 1);
  }
  critic_input = PrivilegedCriticInput(critic_input, critic_observations);
  return {action_net_->forward(mlp_extractor_->policy_net->forward(actor_input)),
          value_net_->forward(mlp_extractor_->value_net->forward(critic_input)), next_states};
}

std::vector<torch::Tensor> ActorCriticImpl::TrainableParameters() const {
  std::vector<torch::Tensor> trainable;
  for (const torch::Tensor& parameter : parameters()) {
    if (parameter.requires_grad()) trainable.push_back(parameter);
  }
  return trainable;
}

std::vector<torch::Tensor> ActorCriticImpl::CriticParameters() const {
  std::vector<torch::Tensor> critic = mlp_extractor_->value_net->parameters();
  for (const torch::Tensor& parameter : value_net_->parameters()) critic.push_back(parameter);
  if (critic_recurrent_) {
    for (const torch::Tensor& parameter : critic_recurrent_->parameters()) {
      critic.push_back(parameter);
    }
  }
  return critic;
}

}  // namespace colav

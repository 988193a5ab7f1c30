#include "models/actor_critic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "env/environment_spec.h"
#include "models/torchscript_export.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

// W W^T (rows <= columns) or W^T W (rows > columns): gain^2 times the identity.
void ExpectOrthogonal(const torch::Tensor& weight, double gain) {
  const torch::Tensor w = weight.detach().to(torch::kFloat64);
  const torch::Tensor gram = w.size(0) <= w.size(1) ? w.mm(w.t()) : w.t().mm(w);
  const torch::Tensor expected = gain * gain * torch::eye(gram.size(0), torch::kFloat64);
  EXPECT_LT((gram - expected).abs().max().item<double>(), 1e-5 * std::max(1.0, gain * gain))
      << "shape " << weight.sizes();
}

std::vector<torch::nn::Linear> Linears(torch::nn::Sequential& trunk) {
  std::vector<torch::nn::Linear> linears;
  for (const auto& child : trunk->children()) {
    if (auto linear = std::dynamic_pointer_cast<torch::nn::LinearImpl>(child)) {
      linears.emplace_back(linear);
    }
  }
  return linears;
}

TEST(ActorCriticTest, OrthogonalInitialisationGainsAndZeroBiases) {
  ActorCritic model(ActorCriticOptions{});
  for (auto* trunk : {&model->mlp_extractor()->policy_net, &model->mlp_extractor()->value_net}) {
    const auto linears = Linears(*trunk);
    ASSERT_EQ(linears.size(), 3U);
    for (const auto& linear : linears) {
      ExpectOrthogonal(linear->weight, std::sqrt(2.0));
      EXPECT_EQ(linear->bias.abs().max().item<float>(), 0.0f);
    }
  }
  ExpectOrthogonal(model->action_net()->weight, 0.01);
  ExpectOrthogonal(model->value_net()->weight, 1.0);
  EXPECT_EQ(model->action_net()->bias.abs().max().item<float>(), 0.0f);
  EXPECT_EQ(model->value_net()->bias.abs().max().item<float>(), 0.0f);
  EXPECT_TRUE(torch::equal(model->log_std(), torch::zeros({kActionSize})));
}

TEST(ActorCriticTest, ArchitectureAndStateDictNamesFollowStableBaselines3) {
  ActorCritic model(ActorCriticOptions{});
  const auto parameters = model->named_parameters();
  for (const char* name :
       {"features_extractor.perception.0.weight", "mlp_extractor.policy_net.0.weight",
        "mlp_extractor.policy_net.4.bias", "mlp_extractor.value_net.2.weight", "action_net.weight",
        "value_net.bias", "log_std"}) {
    EXPECT_NE(parameters.find(name), nullptr) << name;
  }
  EXPECT_EQ(parameters["mlp_extractor.policy_net.0.weight"].sizes(), (at::IntArrayRef{128, 18}));
  EXPECT_EQ(parameters["mlp_extractor.value_net.4.weight"].sizes(), (at::IntArrayRef{32, 64}));
  const auto [mean, value] = model->forward(torch::rand({5, kObservationSize}));
  EXPECT_EQ(mean.sizes(), (at::IntArrayRef{5, kActionSize}));
  EXPECT_EQ(value.sizes(), (at::IntArrayRef{5, 1}));
}

TEST(ActorCriticTest, InitialisationIsAFunctionOfTheSeed) {
  ActorCriticOptions options;
  options.seed = 7;
  ActorCritic a(options), b(options);
  options.seed = 8;
  ActorCritic c(options);
  const auto pa = a->parameters(), pb = b->parameters(), pc = c->parameters();
  for (std::size_t i = 0; i < pa.size(); ++i) EXPECT_TRUE(torch::equal(pa[i], pb[i]));
  EXPECT_FALSE(torch::equal(a->action_net()->weight, c->action_net()->weight));
  // The baseline conv keeps PyTorch's default init range U(+-1/sqrt(45)), from the same seed.
  const torch::Tensor conv = a->features_extractor()->layers()[0].conv->weight;
  EXPECT_LE(conv.abs().max().item<double>(), 1.0 / std::sqrt(45.0));
  EXPECT_FALSE(torch::equal(conv, c->features_extractor()->layers()[0].conv->weight));
}

TEST(ActorCriticTest, PretrainedEncoderKeepsItsWeights) {
  testing_util::TemporaryFolder directory;
  torch::manual_seed(3);
  VaeEncoder encoder(VaeEncoderOptions{VaeArchitecture::kDeep, 12});
  ExportEncoder(encoder, ObservationSettings{}, directory.path() / "encoder.pt");
  for (const bool locked : {true, false}) {
    ActorCriticOptions options;
    options.extractor.kind = ExtractorKind::kVaeDeep;
    options.extractor.encoder = directory.path() / "encoder.pt";
    options.extractor.locked = locked;
    ActorCritic model(options);
    const auto source = encoder->named_parameters();
    const auto target = model->features_extractor()->named_parameters();
    EXPECT_TRUE(torch::equal(target["perception.0.weight"], source["convs.0.weight"]));
    EXPECT_TRUE(torch::equal(target["perception.2.bias"], source["convs.2.bias"]));
    EXPECT_TRUE(torch::equal(target["perception.3.weight"], source["fc_mu.weight"]));
    EXPECT_TRUE(torch::equal(target["perception.3.bias"], source["fc_mu.bias"]));
    const torch::Tensor scans = torch::rand({4, kNumRays});
    EXPECT_TRUE(torch::allclose(model->features_extractor()->Perception(scans), encoder->Mu(scans),
                                1e-5, 1e-6));
    const std::size_t trainable = model->TrainableParameters().size();
    const std::size_t all = model->parameters().size();
    EXPECT_EQ(trainable, locked ? all - 8 : all);  // 3 convs + fc_mu, weight and bias each
  }
}

// The authors' agents: pre-trained convs, then fc_mu re-drawn orthogonal x sqrt 2 with zero bias
// and a ReLU (reference-learning 6.2).
TEST(ActorCriticTest, ReferenceHeadRedrawsFcMuOrthogonalAndAddsARelu) {
  testing_util::TemporaryFolder directory;
  torch::manual_seed(4);
  VaeEncoder encoder(VaeEncoderOptions{VaeArchitecture::kShallow, 12});
  ExportEncoder(encoder, ObservationSettings{}, directory.path() / "encoder.pt");
  ActorCriticOptions options;
  options.extractor.kind = ExtractorKind::kVaeShallow;
  options.extractor.encoder = directory.path() / "encoder.pt";
  options.extractor.head = EncoderHead::kReference;
  ActorCritic model(options);
  const auto source = encoder->named_parameters();
  const auto target = model->features_extractor()->named_parameters();
  EXPECT_TRUE(torch::equal(target["perception.0.weight"], source["convs.0.weight"]));
  const torch::Tensor w = target["perception.1.weight"];
  EXPECT_FALSE(torch::allclose(w, source["fc_mu.weight"]));
  EXPECT_TRUE(torch::allclose(torch::matmul(w, w.t()), 2.0 * torch::eye(12), 1e-5, 1e-5));
  EXPECT_EQ(target["perception.1.bias"].abs().max().item<float>(), 0.0f);
  EXPECT_FALSE(w.requires_grad());  // locked: the random map stays frozen
  const torch::Tensor scans = torch::rand({64, kNumRays});
  const torch::Tensor features = model->features_extractor()->Perception(scans);
  EXPECT_GE(features.min().item<float>(), 0.0f);
  // The ReLU of the orthogonal map of the conv output, by hand.
  const torch::Tensor conv = encoder->Features(scans);
  EXPECT_TRUE(torch::allclose(features, torch::relu(torch::matmul(conv, w.t())), 1e-5, 1e-6));
  // The same seed draws the same map; the paper's head keeps fc_mu.
  options.extractor.head = EncoderHead::kMu;
  EXPECT_TRUE(torch::equal(
      ActorCritic(options)->features_extractor()->named_parameters()["perception.1.weight"],
      source["fc_mu.weight"]));
}

// The critic's loss reaches the GRU only with value_trains_memory; the actor's always does, and
// both settings compute the same forward.
TEST(ActorCriticTest, ValueTrainsMemoryDecidesWhetherTheCriticLossReachesTheGru) {
  ActorCriticOptions options;
  options.recurrent_size = 4;
  torch::manual_seed(2);
  const torch::Tensor observations = torch::rand({3, kObservationSize});
  const torch::Tensor states = torch::randn({3, 4});
  const auto gru_gradient = [&](bool value_trains_memory, bool actor_loss) {
    options.value_trains_memory = value_trains_memory;
    ActorCritic model(options);
    const auto [mean, value, next] = model->forward_recurrent(observations, states);
    (actor_loss ? mean.sum() : value.sum()).backward();
    const torch::Tensor gradient = model->recurrent()->weight_ih.grad();  // undefined: none
    return std::pair{gradient.defined() ? gradient.abs().sum().item<float>() : 0.0f,
                     std::tuple{mean.detach(), value.detach(), next.detach()}};
  };
  const auto [critic_trained, outputs] = gru_gradient(true, false);
  const auto [critic_detached, detached_outputs] = gru_gradient(false, false);
  EXPECT_GT(critic_trained, 0.0f);
  EXPECT_EQ(critic_detached, 0.0f);
  EXPECT_GT(gru_gradient(false, true).first, 0.0f);
  EXPECT_TRUE(torch::equal(std::get<0>(outputs), std::get<0>(detached_outputs)));
  EXPECT_TRUE(torch::equal(std::get<1>(outputs), std::get<1>(detached_outputs)));
  EXPECT_TRUE(torch::equal(std::get<2>(outputs), std::get<2>(detached_outputs)));
}

// A critic with a memory of its own: the actor computes what it computes with the shared memory
// (the critic's GRU is drawn last), each loss reaches its own GRU only, and the state is
// [actor's, critic's].
TEST(ActorCriticTest, SeparateCriticMemoryKeepsEachLossOnItsOwnGru) {
  constexpr std::int64_t kMemory = 4;
  ActorCriticOptions options;
  options.recurrent_size = kMemory;
  torch::manual_seed(3);
  const torch::Tensor observations = torch::rand({3, kObservationSize});
  const torch::Tensor states = torch::randn({3, 2 * kMemory});
  const torch::Tensor actor_states = states.narrow(1, 0, kMemory);
  ActorCritic shared(options);
  options.separate_critic_memory = true;
  ActorCritic separate(options);
  ASSERT_EQ(options.state_size(), 2 * kMemory);

  const auto [shared_mean, shared_value, shared_next] =
      shared->forward_recurrent(observations, actor_states);
  const auto [mean, value, next] = separate->forward_recurrent(observations, states);
  ASSERT_EQ(next.size(1), 2 * kMemory);
  EXPECT_TRUE(torch::allclose(mean, shared_mean));
  EXPECT_TRUE(torch::allclose(next.narrow(1, 0, kMemory), shared_next));
  const torch::Tensor features = separate->features_extractor()->forward(observations);
  const torch::Tensor critic_next =
      separate->critic_recurrent()->forward(features, states.narrow(1, kMemory, kMemory));
  EXPECT_TRUE(torch::allclose(next.narrow(1, kMemory, kMemory), critic_next));
  EXPECT_FALSE(torch::allclose(value, shared_value));  // the critic reads its own state

  const auto gradient_sum = [](const torch::nn::GRUCell& cell) {
    const torch::Tensor gradient = cell->weight_ih.grad();  // undefined: none
    return gradient.defined() ? gradient.abs().sum().item<float>() : 0.0f;
  };
  value.sum().backward({}, /*retain_graph=*/true);
  EXPECT_EQ(gradient_sum(separate->recurrent()), 0.0f);
  EXPECT_GT(gradient_sum(separate->critic_recurrent()), 0.0f);
  separate->zero_grad();
  mean.sum().backward();
  EXPECT_GT(gradient_sum(separate->recurrent()), 0.0f);
  EXPECT_EQ(gradient_sum(separate->critic_recurrent()), 0.0f);
}

// The critic's own parameters are exactly those no action depends on: the action mean's gradient
// reaches every other parameter (the log std aside, which the mean does not read) and none of them.
TEST(ActorCriticTest, CriticParametersAreThoseNoActionReads) {
  ActorCriticOptions options;
  options.recurrent_size = 4;
  options.separate_critic_memory = true;
  ActorCritic model(options);
  const std::vector<torch::Tensor> critic = model->CriticParameters();
  const auto is_critics = [&](const torch::Tensor& parameter) {
    return std::any_of(critic.begin(), critic.end(),
                       [&](const torch::Tensor& c) { return c.is_same(parameter); });
  };
  std::vector<std::string> critic_names;
  for (const auto& named : model->named_parameters()) {
    if (is_critics(named.value())) critic_names.push_back(named.key());
  }
  EXPECT_EQ(critic_names, (std::vector<std::string>{
                              "critic_recurrent.weight_ih", "critic_recurrent.weight_hh",
                              "critic_recurrent.bias_ih", "critic_recurrent.bias_hh",
                              "mlp_extractor.value_net.0.weight", "mlp_extractor.value_net.0.bias",
                              "mlp_extractor.value_net.2.weight", "mlp_extractor.value_net.2.bias",
                              "mlp_extractor.value_net.4.weight", "mlp_extractor.value_net.4.bias",
                              "value_net.weight", "value_net.bias"}));
  torch::manual_seed(4);
  const auto [mean, value, next] =
      model->forward_recurrent(torch::rand({3, kObservationSize}), torch::randn({3, 8}));
  mean.sum().backward();
  for (const auto& named : model->named_parameters()) {
    const torch::Tensor gradient = named.value().grad();
    const bool reached = gradient.defined() && gradient.abs().sum().item<float>() > 0;
    EXPECT_EQ(reached, !is_critics(named.value()) && named.key() != "log_std") << named.key();
  }
}

}  // namespace
}  // namespace colav

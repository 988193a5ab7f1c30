#include "models/actor_critic_fast.h"

#include <gtest/gtest.h>

#include <cmath>

#include "env/environment_spec.h"
#include "models/torchscript_export.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

constexpr int kBatch = 13;  // not a multiple of the vector width: exercises the tails

ActorCriticOptions Options(ExtractorKind kind, const std::filesystem::path& folder, bool locked,
                           EncoderHead head = EncoderHead::kMu, std::int64_t scans = 1) {
  ActorCriticOptions options;
  options.extractor.kind = kind;
  options.extractor.locked = locked;
  options.extractor.head = head;
  options.extractor.scans = scans;
  options.seed = 11;
  if (kind != ExtractorKind::kBaseline) {
    const auto architecture =
        kind == ExtractorKind::kVaeDeep ? VaeArchitecture::kDeep : VaeArchitecture::kShallow;
    torch::manual_seed(2);
    options.extractor.encoder = folder / "encoder.pt";
    ExportEncoder(VaeEncoder(VaeEncoderOptions{architecture, 12}), ObservationSettings{},
                  options.extractor.encoder);
  }
  return options;
}

torch::Tensor Observations(int B, ActorCritic& model) {
  torch::Tensor obs = torch::rand({B, model->features_extractor()->observation_size()});
  obs.narrow(1, 0, kNavigationSize).mul_(4.0).sub_(2.0);
  return obs;
}

// |fast - reference| <= tolerance * max(min_scale, largest |reference|), elementwise.
void ExpectClose(const float* fast, const torch::Tensor& reference, double tolerance,
                 const std::string& what, double min_scale = 1e-3) {
  const torch::Tensor expected = reference.detach().contiguous().flatten();
  const double scale = std::max(min_scale, expected.abs().max().item<double>());
  for (int i = 0; i < expected.numel(); ++i) {
    ASSERT_NEAR(fast[i], expected[i].item<double>(), tolerance * scale) << what << " [" << i << "]";
  }
}

class FastActorCriticTest
    : public ::testing::TestWithParam<std::tuple<ExtractorKind, bool, EncoderHead, int>> {};

// The fast passes' gradients against the reference's. A gradient's rounding error scales with the
// terms it sums, not with their sum: a one-element bias gradient sums thousands of terms, which a
// draw can nearly cancel (0.0015 where it is usually about 1, its error still 3e-6), so every
// gradient is compared on the scale of the model's largest.
void ExpectGradientsClose(FastActorCritic& fast, ActorCritic& reference) {
  const auto parameters = reference->TrainableParameters();
  ASSERT_EQ(fast.gradients().size(), parameters.size());
  double largest = 0;
  for (const torch::Tensor& parameter : parameters) {
    largest = std::max(largest, parameter.grad().abs().max().item<double>());
  }
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    ExpectClose(fast.gradients()[i].data_ptr<float>(), parameters[i].grad(), 1e-4,
                "gradient " + std::to_string(i), largest);
  }
}

// The reference's outputs on a batch and the gradients a test sends back through them.
struct ReferencePass {
  torch::Tensor mean, value;                          // [B, 2], [B, 1]
  torch::Tensor grad_mean, grad_value, grad_log_std;  // [B, 2], [B], [2]
};

// The fast training passes over `obs` (through their features when the extractor is frozen): the
// forward against the reference's mean and value, the backward of its output gradients against
// the gradients autograd left in `reference`.
void ExpectTrainingPassesMatch(FastActorCritic& fast, ActorCritic& reference,
                               const torch::Tensor& obs, const ReferencePass& pass) {
  const int B = static_cast<int>(obs.size(0));
  std::vector<float> features(static_cast<std::size_t>(B) * fast.features_dim());
  fast.Features(obs.data_ptr<float>(), B, features.data());
  std::vector<const float*> rows(B);
  for (int b = 0; b < B; ++b) {
    rows[b] =
        fast.extractor_trainable() ? obs[b].data_ptr<float>() : &features[b * fast.features_dim()];
  }
  if (fast.extractor_trainable()) {
    fast.ForwardObservations(rows.data(), B);
  } else {
    fast.ForwardFeatures(rows.data(), B);
  }
  ExpectClose(fast.mean(), pass.mean.t(), 1e-5, "mean");
  ExpectClose(fast.value(), pass.value, 1e-5, "value");
  torch::Tensor d_mean = pass.grad_mean.t().contiguous();
  torch::Tensor d_value = pass.grad_value.clone();
  fast.Backward(d_mean.data_ptr<float>(), d_value.data_ptr<float>(),
                pass.grad_log_std.data_ptr<float>(), B);
  ExpectGradientsClose(fast, reference);
}

// The reference comes from a float64 copy of the model. The fast passes and LibTorch in float32
// sum thousands of terms per convolution weight, each in its own order, so both results carry
// rounding errors; against float64 only the fast passes' own remain.
ActorCritic DoublePrecisionCopy(ActorCritic& model, const ActorCriticOptions& options) {
  ActorCritic copy(options);
  torch::NoGradGuard no_grad;
  const auto source = model->parameters();
  const auto target = copy->parameters();
  for (std::size_t i = 0; i < source.size(); ++i) target[i].copy_(source[i]);
  copy->to(torch::kFloat64);
  return copy;
}

TEST_P(FastActorCriticTest, ForwardAndGradientsMatchAutograd) {
  const auto [kind, locked, head, scans] = GetParam();
  testing_util::TemporaryFolder directory;
  const ActorCriticOptions options = Options(kind, directory.path(), locked, head, scans);
  ActorCritic model(options);
  FastActorCritic fast(model, kBatch);
  EXPECT_EQ(fast.extractor_trainable(), kind == ExtractorKind::kBaseline || !locked);
  EXPECT_EQ(fast.observation_size(), kNavigationSize + scans * kNumRays);

  const torch::Tensor obs = Observations(kBatch, model);
  const torch::Tensor grad_mean = torch::randn({kBatch, kActionSize});
  const torch::Tensor grad_value = torch::randn({kBatch});
  const torch::Tensor grad_log_std = torch::randn({kActionSize});
  ActorCritic reference = DoublePrecisionCopy(model, options);
  auto [mean, value] = reference->forward(obs.to(torch::kFloat64));
  const torch::Tensor loss = (mean * grad_mean).sum() + (value.squeeze(1) * grad_value).sum() +
                             (reference->log_std() * grad_log_std).sum();
  loss.backward();

  std::vector<float> features(static_cast<std::size_t>(kBatch) * fast.features_dim());
  fast.Features(obs.data_ptr<float>(), kBatch, features.data());
  ExpectClose(features.data(), reference->features_extractor()->forward(obs.to(torch::kFloat64)),
              1e-5, "features");
  ExpectTrainingPassesMatch(fast, reference, obs,
                            {mean, value, grad_mean, grad_value, grad_log_std});
}

INSTANTIATE_TEST_SUITE_P(
    Extractors, FastActorCriticTest,
    ::testing::Values(std::tuple{ExtractorKind::kBaseline, false, EncoderHead::kMu, 1},
                      std::tuple{ExtractorKind::kVaeShallow, true, EncoderHead::kMu, 1},
                      std::tuple{ExtractorKind::kVaeShallow, false, EncoderHead::kMu, 1},
                      std::tuple{ExtractorKind::kVaeDeep, true, EncoderHead::kMu, 1},
                      std::tuple{ExtractorKind::kVaeDeep, false, EncoderHead::kMu, 1},
                      std::tuple{ExtractorKind::kVaeShallow, true, EncoderHead::kReference, 1},
                      std::tuple{ExtractorKind::kVaeDeep, false, EncoderHead::kReference, 1},
                      // Scan history: three scans through one shared perception stack.
                      std::tuple{ExtractorKind::kBaseline, false, EncoderHead::kMu, 3},
                      std::tuple{ExtractorKind::kVaeShallow, true, EncoderHead::kMu, 3},
                      std::tuple{ExtractorKind::kVaeDeep, false, EncoderHead::kReference, 3}));

class FastActorCriticPredictTest : public ::testing::TestWithParam<std::tuple<ExtractorKind, int>> {
};

TEST_P(FastActorCriticPredictTest, PredictAndFeaturesMatchTheModel) {
  const auto [kind, scans] = GetParam();
  testing_util::TemporaryFolder directory;
  const ActorCriticOptions options =
      Options(kind, directory.path(), /*locked=*/true, EncoderHead::kMu, scans);
  ActorCritic model(options);
  constexpr int kMaxBatch = 5;
  FastActorCritic fast(model, kMaxBatch);
  const torch::Tensor obs = Observations(kBatch, model);
  ActorCritic reference = DoublePrecisionCopy(model, options);
  torch::NoGradGuard no_grad;
  // Features of more observations than max_batch: in chunks.
  std::vector<float> features(static_cast<std::size_t>(kBatch) * fast.features_dim());
  fast.Features(obs.data_ptr<float>(), kBatch, features.data());
  ExpectClose(features.data(), reference->features_extractor()->forward(obs.to(torch::kFloat64)),
              1e-5, "features");

  const torch::Tensor batch = obs.narrow(0, 0, kMaxBatch);
  std::vector<float> mean(kMaxBatch * kActionSize), value(kMaxBatch);
  fast.Predict(batch.data_ptr<float>(), kMaxBatch, mean.data(), value.data());
  const auto [expected_mean, expected_value] = reference->forward(batch.to(torch::kFloat64));
  ExpectClose(mean.data(), expected_mean, 1e-5, "mean");
  ExpectClose(value.data(), expected_value, 1e-5, "value");
}

INSTANTIATE_TEST_SUITE_P(Extractors, FastActorCriticPredictTest,
                         ::testing::Values(std::tuple{ExtractorKind::kBaseline, 1},
                                           std::tuple{ExtractorKind::kBaseline, 3},
                                           std::tuple{ExtractorKind::kVaeDeep, 3}));

// A privileged critic (critic_vessels 2): its trunk reads [features; critic observations]. The
// training passes, whose critic gradient reaches a trainable extractor through the feature rows
// only, and Predict, against autograd; changing the critic observations moves the value alone.
class FastPrivilegedCriticTest : public ::testing::TestWithParam<std::tuple<ExtractorKind, bool>> {
};

TEST_P(FastPrivilegedCriticTest, ForwardGradientsAndPredictMatchAutograd) {
  const auto [kind, locked] = GetParam();
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options = Options(kind, directory.path(), locked);
  options.critic_vessels = 2;
  ActorCritic model(options);
  FastActorCritic fast(model, kBatch);
  ASSERT_EQ(fast.critic_observation_size(), 2 * kCriticValuesPerVessel);
  ASSERT_EQ(model->mlp_extractor()->value_net->parameters()[0].size(1),
            fast.features_dim() + 2 * kCriticValuesPerVessel);

  const torch::Tensor obs = Observations(kBatch, model);
  const torch::Tensor critic_obs = torch::randn({kBatch, fast.critic_observation_size()});
  const torch::Tensor grad_mean = torch::randn({kBatch, kActionSize});
  const torch::Tensor grad_value = torch::randn({kBatch});
  const torch::Tensor grad_log_std = torch::randn({kActionSize});
  ActorCritic reference = DoublePrecisionCopy(model, options);
  auto [mean, value] = reference->forward(obs.to(torch::kFloat64), critic_obs.to(torch::kFloat64));
  ((mean * grad_mean).sum() + (value.squeeze(1) * grad_value).sum() +
   (reference->log_std() * grad_log_std).sum())
      .backward();

  std::vector<const float*> critic_rows(kBatch);
  for (int b = 0; b < kBatch; ++b) critic_rows[b] = critic_obs[b].data_ptr<float>();
  fast.SetCriticObservations(critic_rows.data());
  ExpectTrainingPassesMatch(fast, reference, obs,
                            {mean, value, grad_mean, grad_value, grad_log_std});

  std::vector<float> predicted_mean(kBatch * kActionSize), predicted_value(kBatch);
  fast.Predict(obs.data_ptr<float>(), kBatch, predicted_mean.data(), predicted_value.data(),
               nullptr, critic_obs.data_ptr<float>());
  ExpectClose(predicted_mean.data(), mean, 1e-5, "Predict's mean");
  ExpectClose(predicted_value.data(), value, 1e-5, "Predict's value");
  const torch::Tensor other_critic_obs = critic_obs + 1.0;
  std::vector<float> other_mean(kBatch * kActionSize), other_value(kBatch);
  fast.Predict(obs.data_ptr<float>(), kBatch, other_mean.data(), other_value.data(), nullptr,
               other_critic_obs.data_ptr<float>());
  EXPECT_EQ(other_mean, predicted_mean) << "the actor does not read the critic observations";
  EXPECT_NE(other_value, predicted_value);
}

INSTANTIATE_TEST_SUITE_P(Extractors, FastPrivilegedCriticTest,
                         ::testing::Values(std::tuple{ExtractorKind::kBaseline, false},
                                           std::tuple{ExtractorKind::kVaeShallow, true}));

// Which losses train which memory.
enum class MemoryTraining {
  kBothLosses,  ///< one GRU, trained by the actor's and the critic's loss
  kActorLoss,   ///< one GRU, trained by the actor's loss only (value_trains_memory false)
  kSeparate,    ///< a GRU each (separate_critic_memory)
};

// A recurrent model on 3 sequences of 4 steps (time-major samples), an episode starting at step 2
// of sequence 1: the fast passes against autograd through forward_recurrent step by step, for
// each way of training the memory, with the paper's critic and with a privileged one (critic
// observations of 2 vessels after the state the critic reads).
class FastRecurrentTest : public ::testing::TestWithParam<
                              std::tuple<std::tuple<ExtractorKind, bool>, MemoryTraining, int>> {};

TEST_P(FastRecurrentTest, SequencesForwardAndBackwardMatchAutograd) {
  const auto [extractor, memory_training, critic_vessels] = GetParam();
  const auto [kind, locked] = extractor;
  constexpr int kSequences = 3, kSteps = 4, kMemory = 5, B = kSequences * kSteps;
  testing_util::TemporaryFolder directory;
  ActorCriticOptions options = Options(kind, directory.path(), locked);
  options.recurrent_size = kMemory;
  options.value_trains_memory = memory_training != MemoryTraining::kActorLoss;
  options.separate_critic_memory = memory_training == MemoryTraining::kSeparate;
  options.critic_vessels = critic_vessels;
  ActorCritic model(options);
  FastActorCritic fast(model, kBatch);
  ASSERT_EQ(fast.recurrent_size(), kMemory);
  const int state_size = memory_training == MemoryTraining::kSeparate ? 2 * kMemory : kMemory;
  ASSERT_EQ(fast.state_size(), state_size);
  const int critic_size = critic_vessels * kCriticValuesPerVessel;
  ASSERT_EQ(model->mlp_extractor()->value_net->parameters()[0].size(1),
            fast.features_dim() + kMemory + critic_size);

  const torch::Tensor obs = Observations(B, model);
  const torch::Tensor critic_obs = torch::randn({B, critic_size});
  // The critic observations of samples [start, start + count), or none for the paper's critic.
  const auto critic_slice = [&](int start, int count) {
    return critic_size == 0 ? torch::Tensor()
                            : critic_obs.narrow(0, start, count).to(torch::kFloat64);
  };
  const torch::Tensor initial = torch::randn({kSequences, state_size});
  std::vector<std::uint8_t> reset(B, 0);
  reset[2 * kSequences + 1] = 1;
  const torch::Tensor grad_mean = torch::randn({B, kActionSize});
  const torch::Tensor grad_value = torch::randn({B});
  const torch::Tensor grad_log_std = torch::randn({kActionSize});
  ActorCritic reference = DoublePrecisionCopy(model, options);
  torch::Tensor state = initial.to(torch::kFloat64);
  std::vector<torch::Tensor> means, values;
  for (int t = 0; t < kSteps; ++t) {
    torch::Tensor keep = torch::ones({kSequences, 1}, torch::kFloat64);
    for (int s = 0; s < kSequences; ++s) keep[s][0] = reset[t * kSequences + s] ? 0.0f : 1.0f;
    auto [mean, value, next] =
        reference->forward_recurrent(obs.narrow(0, t * kSequences, kSequences).to(torch::kFloat64),
                                     state * keep, critic_slice(t * kSequences, kSequences));
    means.push_back(mean);
    values.push_back(value);
    state = next;
  }
  const torch::Tensor mean = torch::cat(means), value = torch::cat(values);
  const torch::Tensor loss = (mean * grad_mean).sum() + (value.squeeze(1) * grad_value).sum() +
                             (reference->log_std() * grad_log_std).sum();
  loss.backward();

  std::vector<const float*> rows(B), initial_rows(kSequences);
  for (int b = 0; b < B; ++b) rows[b] = obs[b].data_ptr<float>();
  for (int s = 0; s < kSequences; ++s) initial_rows[s] = initial[s].data_ptr<float>();
  std::vector<float> features(static_cast<std::size_t>(B) * fast.features_dim());
  fast.SetSequences(initial_rows.data(), reset.data(), kSequences);
  std::vector<const float*> critic_rows(B);
  for (int b = 0; b < B; ++b) critic_rows[b] = critic_obs.data_ptr<float>() + b * critic_size;
  if (critic_size > 0) fast.SetCriticObservations(critic_rows.data());
  if (fast.extractor_trainable()) {
    fast.ForwardObservations(rows.data(), B);
  } else {
    fast.Features(obs.data_ptr<float>(), B, features.data());
    for (int b = 0; b < B; ++b) rows[b] = &features[b * fast.features_dim()];
    fast.ForwardFeatures(rows.data(), B);
  }
  ExpectClose(fast.mean(), mean.t(), 1e-5, "mean");
  ExpectClose(fast.value(), value, 1e-5, "value");
  torch::Tensor d_mean = grad_mean.t().contiguous();
  torch::Tensor d_value = grad_value.clone();
  fast.Backward(d_mean.data_ptr<float>(), d_value.data_ptr<float>(), grad_log_std.data_ptr<float>(),
                B);
  ExpectGradientsClose(fast, reference);

  // Predict: one step of each row from its state, the states replaced by the next ones.
  torch::NoGradGuard no_grad;
  const torch::Tensor batch = obs.narrow(0, 0, kSequences);
  torch::Tensor states = initial.clone();
  std::vector<float> predicted_mean(kSequences * kActionSize), predicted_value(kSequences);
  fast.Predict(batch.data_ptr<float>(), kSequences, predicted_mean.data(), predicted_value.data(),
               states.data_ptr<float>(), critic_size > 0 ? critic_obs.data_ptr<float>() : nullptr);
  const auto [step_mean, step_value, step_state] = reference->forward_recurrent(
      batch.to(torch::kFloat64), initial.to(torch::kFloat64), critic_slice(0, kSequences));
  ExpectClose(predicted_mean.data(), step_mean, 1e-5, "predicted mean");
  ExpectClose(predicted_value.data(), step_value, 1e-5, "predicted value");
  ExpectClose(states.data_ptr<float>(), step_state, 1e-5, "next states");
}

// A trainable baseline and a locked VAE encoder, each with every way of training the memory and
// both critics.
INSTANTIATE_TEST_SUITE_P(
    Extractors, FastRecurrentTest,
    ::testing::Combine(::testing::Values(std::tuple{ExtractorKind::kBaseline, false},
                                         std::tuple{ExtractorKind::kVaeShallow, true}),
                       ::testing::Values(MemoryTraining::kBothLosses, MemoryTraining::kActorLoss,
                                         MemoryTraining::kSeparate),
                       ::testing::Values(0, 2)));

TEST(ActorCriticKernelsTest, TanhIsAccurate) {
  std::vector<float> x;
  for (float v = -12.0f; v <= 12.0f; v += 0.001f) x.push_back(v);
  std::vector<float> y = x;
  kernels::TanhInPlace(y.data(), static_cast<int>(y.size()));
  for (std::size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(y[i], std::tanh(x[i]), 3e-7) << x[i];
}

// Rows in blocks of 4, then a pair, then one by one: M = 5, 6 and 7 take every remainder; N = 19
// has a tail of 3 columns past its vector lanes.
TEST(ActorCriticKernelsTest, MatMulWithStridesAndTails) {
  for (const int M : {5, 6, 7}) {
    const torch::Tensor a = torch::randn({7, M});
    const torch::Tensor b = torch::randn({7, 19});
    std::vector<float> c(M * 19, 1.0f);
    // C = A^T B: A(m, k) = a[k, m]
    kernels::MatMul(c.data(), 19, a.data_ptr<float>(), 1, M, b.data_ptr<float>(), 19, M, 19, 7,
                    /*accumulate=*/true);
    ExpectClose(c.data(), a.t().mm(b) + 1.0, 1e-5, "C, M = " + std::to_string(M));
  }
}

}  // namespace
}  // namespace colav

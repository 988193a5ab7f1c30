// Every policy runs under the observation settings it was trained with (recorded in its file or
// given by its sidecar), so policies trained under different settings are evaluated paired in one
// run, and none silently under the evaluation's settings.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "eval/episode_runner.h"
#include "models/observation_settings_record.h"
#include "tests/eval/test_policies.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using ::testing::HasSubstr;
using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;
namespace tp = testing_policies;

constexpr ObservationSettings kLinear{ClosenessTransform::kLinear};
constexpr ObservationSettings kLog{ClosenessTransform::kLog};

EnvironmentConfig ShortTestEpisodes(ClosenessTransform closeness) {
  EnvironmentConfig config;
  config.test_mode = true;
  config.max_steps = 300;
  config.closeness = closeness;
  return config;
}

std::vector<EpisodeMetrics> Metrics(const std::vector<EpisodeOutcome>& outcomes) {
  std::vector<EpisodeMetrics> metrics;
  for (const EpisodeOutcome& outcome : outcomes) metrics.push_back(outcome.metrics);
  return metrics;
}

void ExpectSameMetrics(const std::vector<EpisodeMetrics>& a, const std::vector<EpisodeMetrics>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t e = 0; e < a.size(); ++e) {
    EXPECT_EQ(a[e].steps, b[e].steps) << e;
    EXPECT_EQ(a[e].mean_abs_cte, b[e].mean_abs_cte) << e;
    EXPECT_EQ(a[e].cumulative_reward, b[e].cumulative_reward) << e;
  }
}

bool AnyDifferent(const std::vector<EpisodeMetrics>& a, const std::vector<EpisodeMetrics>& b) {
  for (std::size_t e = 0; e < a.size(); ++e) {
    if (a[e].steps != b[e].steps || a[e].mean_abs_cte != b[e].mean_abs_cte) return true;
  }
  return false;
}

class PolicySettingsTest : public ::testing::Test {
 protected:
  // ReactivePolicy(seed) saved as `name`.pt, recording `settings` when given.
  Policy Reactive(std::uint64_t seed, const std::string& name,
                  std::optional<ObservationSettings> settings) {
    torch::jit::Module module = tp::ReactivePolicy(seed);
    if (settings) RecordObservationSettings(module, *settings);
    return Policy(tp::SavePolicy(module, folder_ / (name + ".pt")), name);
  }
  std::vector<EpisodeMetrics> RunAlone(Policy policy, ClosenessTransform env) {
    std::vector<Policy> policies = {std::move(policy)};
    return Metrics(RunEpisodes(policies, episodes_, ShortTestEpisodes(env), 2)[0]);
  }
  TemporaryFolder folder_;
  const std::vector<EvaluationEpisode> episodes_ = TestEpisodes(5, 4);
};

TEST_F(PolicySettingsTest, PoliciesOfDifferentSettingsRunPairedEachUnderItsOwn) {
  std::vector<Policy> together = {Reactive(1, "trained_log", kLog),
                                  Reactive(2, "trained_linear", kLinear)};
  EXPECT_EQ(together[0].settings_origin(), "recorded in the file");
  const auto outcomes =
      RunEpisodes(together, episodes_, ShortTestEpisodes(ClosenessTransform::kLinear), 2);
  // Each equals the same weights run alone in an environment of its own transform.
  ExpectSameMetrics(Metrics(outcomes[0]),
                    RunAlone(Reactive(1, "bare_log", std::nullopt), ClosenessTransform::kLog));
  ExpectSameMetrics(Metrics(outcomes[1]), RunAlone(Reactive(2, "bare_linear", std::nullopt),
                                                   ClosenessTransform::kLinear));
  // The evaluation's linear default would have given the log policy other episodes.
  EXPECT_TRUE(AnyDifferent(Metrics(outcomes[0]), RunAlone(Reactive(1, "bare_log", std::nullopt),
                                                          ClosenessTransform::kLinear)));
}

TEST_F(PolicySettingsTest, ASidecarGivesTheSettingsOfAFileThatRecordsNone) {
  Policy bare = Reactive(3, "agent", std::nullopt);
  EXPECT_FALSE(bare.own_settings().has_value());
  EXPECT_EQ(bare.SettingsOr(kLinear), kLinear);

  testing_util::WriteFile(SidecarPath(folder_ / "agent.pt"), "env:\n  closeness: log\n");
  const Policy with_sidecar(folder_ / "agent.pt", "agent");
  EXPECT_EQ(with_sidecar.own_settings(), kLog);
  EXPECT_EQ(with_sidecar.settings_origin(), "sidecar " + (folder_ / "agent.pt.yaml").string());
  ExpectSameMetrics(RunAlone(with_sidecar, ClosenessTransform::kLinear),
                    RunAlone(bare, ClosenessTransform::kLog));
}

TEST_F(PolicySettingsTest, ABadSidecarIsAOneLineErrorNamingIt) {
  Reactive(4, "agent", std::nullopt);
  const std::filesystem::path sidecar = SidecarPath(folder_ / "agent.pt");
  testing_util::WriteFile(sidecar, "env:\n  closeness: square\n");
  EXPECT_THAT(UserErrorMessage([&] { Policy(folder_ / "agent.pt", "agent"); }),
              HasSubstr(sidecar.string() + ": key 'env.closeness' = 'square'"));
}

}  // namespace
}  // namespace colav

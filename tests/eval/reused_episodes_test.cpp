// Episodes an earlier evaluation lends a new one (evaluate --reuse): only a model of the same
// name and fingerprint, run under the same settings on the same scenarios, and to the bit.
#include "eval/reused_episodes.h"

#include <gtest/gtest.h>

#include "eval/episode_table.h"
#include "eval/policy_fingerprint.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::WriteFile;

ConfigSchema TinySchema() {
  ConfigSchema schema;
  schema.AddInt("eval.seed", 1, "test scenarios' master seed", 0, 1000);
  schema.AddInt("eval.threads", 0, "threads", 0, 256);
  schema.AddDouble("env.goal_radius", 5.0, "goal radius", 0.0, 100.0);
  return schema;
}

EpisodeMetrics Metrics(double progress, bool collision) {
  EpisodeMetrics metrics;
  metrics.progress = progress;
  metrics.mean_abs_cte = progress * 17.0 / 3.0;  // digits that need all 17 to come back
  metrics.steps = 1234;
  metrics.collision = collision;
  metrics.goal_reached = !collision;
  metrics.cumulative_reward = -0.1 / 3.0;
  metrics.path_length = 400.0 + progress;
  return metrics;
}

EpisodeOutcome Outcome(const EpisodeMetrics& metrics) {
  EpisodeOutcome outcome;
  outcome.metrics = metrics;
  return outcome;
}

void ExpectSameMetrics(const EpisodeMetrics& a, const EpisodeMetrics& b) {
  EXPECT_EQ(a.progress, b.progress);
  EXPECT_EQ(a.mean_abs_cte, b.mean_abs_cte);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.collision, b.collision);
  EXPECT_EQ(a.goal_reached, b.goal_reached);
  EXPECT_EQ(a.truncated, b.truncated);
  EXPECT_EQ(a.cumulative_reward, b.cumulative_reward);
  EXPECT_EQ(a.path_length, b.path_length);
}

// An earlier evaluation of models "a" and "b" on two test scenarios, as evaluate writes it.
class ReusedEpisodesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    episodes_ = {{"test-000", 11, {}}, {"test-001", 12, {}}};
    outcomes_ = {{Outcome(Metrics(0.9871234567, false)), Outcome(Metrics(0.4, true))},
                 {Outcome(Metrics(0.25, true)), Outcome(Metrics(1.0 / 3.0, false))}};
    WriteEvaluation(Config::Defaults(TinySchema()), "fnv1a64:aaaa", "fnv1a64:bbbb");
  }
  void WriteEvaluation(const Config& config, const std::string& a, const std::string& b) {
    WriteFile(folder_ / "config.yaml", config.ToYaml());
    WriteFile(folder_ / "episodes.csv", EpisodeTable({"a", "b"}, episodes_, outcomes_));
    WriteFile(folder_ / "summary.json",
              R"({"scenarios": "test", "seed": 1, "evaluator_build_id": "b1d", "models": [)"
              R"({"name": "a", "policy_fingerprint": ")" +
                  a + R"("}, {"name": "b", "policy_fingerprint": ")" + b + R"("}]})");
  }
  ReusableEpisodes Find(const Config& config, const std::map<std::string, std::string>& wanted,
                        const std::vector<EvaluationEpisode>& episodes,
                        const std::string& build_id = "b1d") const {
    const ConfigSchema schema = TinySchema();
    const std::vector<std::string> free_keys = {"eval.threads"};
    return FindReusableEpisodes(folder_.path(), {config, schema, free_keys, build_id, episodes},
                                wanted);
  }
  TemporaryFolder folder_;
  std::vector<EvaluationEpisode> episodes_;
  std::vector<std::vector<EpisodeOutcome>> outcomes_;
};

TEST_F(ReusedEpisodesTest, AModelOfTheSameNameAndFingerprintLendsItsEpisodesToTheBit) {
  Config config = Config::Defaults(TinySchema());
  config.Set("eval.threads", "2", "test");  // changes no episode
  const ReusableEpisodes reusable = Find(
      config, {{"a", "fnv1a64:aaaa"}, {"b", "fnv1a64:other"}, {"c", "fnv1a64:cccc"}}, episodes_);
  ASSERT_EQ(reusable.by_model.size(), 1U);  // b's file changed, c is new
  const std::vector<EpisodeMetrics>& a = reusable.by_model.at("a");
  ASSERT_EQ(a.size(), 2U);
  ExpectSameMetrics(a[0], outcomes_[0][0].metrics);
  ExpectSameMetrics(a[1], outcomes_[0][1].metrics);
}

TEST_F(ReusedEpisodesTest, OtherSettingsOrScenariosLendNothing) {
  Config other_radius = Config::Defaults(TinySchema());
  other_radius.Set("env.goal_radius", "0.5", "test");
  const std::map<std::string, std::string> both = {{"a", "fnv1a64:aaaa"}, {"b", "fnv1a64:bbbb"}};
  const ReusableEpisodes radius = Find(other_radius, both, episodes_);
  EXPECT_TRUE(radius.by_model.empty());
  EXPECT_NE(radius.why_none.find("env.goal_radius"), std::string::npos) << radius.why_none;
  const Config config = Config::Defaults(TinySchema());
  EXPECT_EQ(Find(config, both, episodes_).by_model.size(), 2U);
  EXPECT_TRUE(Find(config, both, {episodes_[0]}).by_model.empty());  // fewer scenarios
  std::vector<EvaluationEpisode> reseeded = episodes_;
  reseeded[1].seed = 13;
  EXPECT_TRUE(Find(config, both, reseeded).by_model.empty());
  // Another build of evaluate may simulate or act otherwise.
  const ReusableEpisodes rebuilt = Find(config, both, episodes_, "c0de");
  EXPECT_TRUE(rebuilt.by_model.empty());
  EXPECT_NE(rebuilt.why_none.find("another build of evaluate"), std::string::npos)
      << rebuilt.why_none;
}

TEST_F(ReusedEpisodesTest, AMissingOrBrokenEvaluationLendsNothingAndSaysWhy) {
  const Config config = Config::Defaults(TinySchema());
  const std::map<std::string, std::string> a = {{"a", "fnv1a64:aaaa"}};
  WriteFile(folder_ / "summary.json", "{\"scenarios\": ");
  EXPECT_TRUE(Find(config, a, episodes_).by_model.empty());
  WriteFile(folder_ / "summary.json", R"({"scenarios": "files", "models": []})");
  EXPECT_NE(Find(config, a, episodes_).why_none.find("did not run the test scenarios"),
            std::string::npos);
  std::filesystem::remove(folder_ / "summary.json");
  const ReusableEpisodes none = Find(config, a, episodes_);
  EXPECT_TRUE(none.by_model.empty());
  EXPECT_NE(none.why_none.find("holds no evaluation"), std::string::npos) << none.why_none;
}

TEST(PolicyFingerprintTest, ChangesWithTheFileAndItsSidecar) {
  const TemporaryFolder folder;
  const std::filesystem::path policy = folder / "policy.pt";
  WriteFile(policy, "weights");
  const std::string first = PolicyFingerprint(policy);
  EXPECT_EQ(first.rfind("fnv1a64:", 0), 0U);
  EXPECT_EQ(first.size(), 8U + 16U);
  EXPECT_EQ(PolicyFingerprint(policy), first);
  WriteFile(policy.string() + ".yaml", "env:\n  closeness: log\n");
  const std::string with_sidecar = PolicyFingerprint(policy);
  EXPECT_NE(with_sidecar, first);
  WriteFile(policy, "weightz");
  EXPECT_NE(PolicyFingerprint(policy), with_sidecar);
  // FNV-1a 64 of "a", a published test vector.
  WriteFile(folder / "a.pt", "a");
  EXPECT_EQ(PolicyFingerprint(folder / "a.pt"), "fnv1a64:af63dc4c8601ec8c");
}

}  // namespace
}  // namespace colav

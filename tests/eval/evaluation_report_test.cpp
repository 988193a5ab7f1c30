// summary.md in the paper's table form, and summary.json read back.
#include "eval/evaluation_report.h"

#include <gtest/gtest.h>

#include "src/atomic_file.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;

std::vector<EpisodeMetrics> Episodes(int count, int collisions, double progress) {
  std::vector<EpisodeMetrics> episodes(count);
  for (int k = 0; k < count; ++k) {
    episodes[k].collision = k < collisions;
    episodes[k].goal_reached = k >= collisions;
    episodes[k].progress = progress + 0.001 * (k % 7);
    episodes[k].mean_abs_cte = 15.0 + k % 11;
    episodes[k].steps = 500 + 3 * (k % 13);
    episodes[k].cumulative_reward = 200.0 + k;
  }
  return episodes;
}

EvaluationReport TwoModelReport() {
  return MakeEvaluationReport("test", 0, {"shallow", "baseline"}, {"s/policy.pt", "b/policy.pt"},
                              {Episodes(100, 5, 0.95), Episodes(100, 4, 0.94)});
}

TEST(EvaluationReport, MarkdownHasThePaperTableAndThePairedDifferences) {
  const std::string markdown = EvaluationReportMarkdown(TwoModelReport());
  EXPECT_NE(markdown.find("| metric | shallow | baseline |"), std::string::npos) << markdown;
  // The paper prints 9.4: it rounded 0.09346 to 0.094 first (reference-learning 7.3).
  EXPECT_NE(markdown.find("| collisions | 5.0 % [0.7, 9.3] | 4.0 % [0.1, 7.9] |"),
            std::string::npos)
      << markdown;
  // The first table: Wilson score intervals for the rates.
  EXPECT_NE(markdown.find("| collisions | 5.0 % [2.2, 11.2] | 4.0 % [1.6, 9.8] |"),
            std::string::npos)
      << markdown;
  EXPECT_LT(markdown.find("[2.2, 11.2]"), markdown.find("[0.7, 9.3]"));
  EXPECT_NE(markdown.find("(95/100)"), std::string::npos) << markdown;
  // Progress differs by exactly one point on every episode: a paired interval of zero width.
  EXPECT_NE(markdown.find("| shallow - baseline | **+1.0 pp [1.0, 1.0]** |"), std::string::npos)
      << markdown;
}

TEST(EvaluationReport, OneModelHasNoDifferences) {
  const EvaluationReport report =
      MakeEvaluationReport("files", std::nullopt, {"a"}, {"a.pt"}, {Episodes(6, 0, 0.9)});
  EXPECT_TRUE(report.differences.empty());
  EXPECT_EQ(EvaluationReportMarkdown(report).find("Paired"), std::string::npos);
  EXPECT_TRUE(EvaluationReportJson(report)["seed"].is_null());
}

TEST(EvaluationReport, JsonRoundTrip) {
  const TemporaryFolder folder;
  const EvaluationReport report = TwoModelReport();
  const nlohmann::ordered_json json = EvaluationReportJson(report);
  EXPECT_EQ(json["paired_differences"].size(), 1U);
  EXPECT_EQ(json["models"][0]["metrics"]["collision"]["n"], 100);
  WriteTextFileAtomically(folder / "summary.json", json.dump(2));
  const std::vector<ModelSummary> models = ReadModelSummaries(folder / "summary.json");
  ASSERT_EQ(models.size(), 2U);
  EXPECT_EQ(models[1].name, "baseline");
  EXPECT_EQ(models[1].policy, "b/policy.pt");
  EXPECT_EQ(models[0].goals_reached, 95);
  for (std::size_t k = 0; k < SummaryMetrics().size(); ++k) {
    EXPECT_EQ(models[0].metrics[k].key, report.models[0].metrics[k].key);
    EXPECT_DOUBLE_EQ(models[0].metrics[k].interval.high, report.models[0].metrics[k].interval.high);
    EXPECT_DOUBLE_EQ(models[0].metrics[k].in_range.low, report.models[0].metrics[k].in_range.low);
  }
  EXPECT_EQ(json["models"][0]["metrics"]["collision"]["in_range"]["method"], "wilson");
  EXPECT_EQ(json["models"][0]["metrics"]["progress"]["in_range"]["method"], "bootstrap");
}

TEST(EvaluationReport, BadSummaryFilesAreOneLineErrors) {
  const TemporaryFolder folder;
  testing_util::WriteFile(folder / "broken.json", "{\"models\": [");
  testing_util::WriteFile(folder / "other.json", "{\"models\": [{\"name\": \"x\"}]}");
  EXPECT_EQ(UserErrorMessage([&] { ReadModelSummaries(folder / "broken.json"); }),
            (folder / "broken.json").string() + ": not valid JSON");
  const std::string message = UserErrorMessage([&] { ReadModelSummaries(folder / "other.json"); });
  EXPECT_NE(message.find("other.json: not an evaluation summary"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_NE(UserErrorMessage([&] {
              ReadModelSummaries(folder / "missing.json");
            }).find("missing.json: cannot read"),
            std::string::npos);
}

}  // namespace
}  // namespace colav

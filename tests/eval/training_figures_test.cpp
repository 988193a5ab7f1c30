// The inputs of the training-curve and beta-sweep figures: CSV logs, rolling statistics, and the
// figures themselves drawn from small constructed data.
#include <gtest/gtest.h>

#include <cmath>

#include "eval/beta_sweep_figure.h"
#include "eval/rolling_statistics.h"
#include "eval/training_curves.h"
#include "src/csv_table.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;
using testing_util::WriteFile;

TEST(RollingStatistics, TrailingWindowWithPartialStart) {
  const std::vector<RollingPoint> points = RollingMeanSd({1.0, 3.0, 5.0, 7.0}, 2);
  ASSERT_EQ(points.size(), 4U);
  EXPECT_DOUBLE_EQ(points[0].mean, 1.0);
  EXPECT_DOUBLE_EQ(points[0].sd, 0.0);
  EXPECT_DOUBLE_EQ(points[1].mean, 2.0);
  EXPECT_DOUBLE_EQ(points[1].sd, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(points[3].mean, 6.0);
  EXPECT_DOUBLE_EQ(RollingMeanSd({1.0, 3.0, 5.0, 7.0}, 100)[3].mean, 4.0);
}

TEST(CsvTable, ReadsColumnsAndSkipsATornLastLine) {
  const TemporaryFolder folder;
  WriteFile(folder / "log.csv", "global_step,progress\n8,0.5\n16,1\n24,0.");
  const CsvTable table = ReadCsvTable(folder / "log.csv");
  EXPECT_EQ(table.rows.size(), 2U);
  EXPECT_EQ(NumericColumn(table, "global_step"), (std::vector<double>{8.0, 16.0}));
  EXPECT_EQ(UserErrorMessage([&] { NumericColumn(table, "reward"); }),
            (folder / "log.csv").string() + ": no column 'reward'");
}

TEST(CsvTable, BadRowsNameTheLine) {
  const TemporaryFolder folder;
  WriteFile(folder / "short.csv", "a,b\n1,2\n3\n");
  EXPECT_EQ(UserErrorMessage([&] { ReadCsvTable(folder / "short.csv"); }),
            (folder / "short.csv").string() + ":3: 1 fields, the header has 2");
  WriteFile(folder / "text.csv", "a,b\n1,x\n");
  EXPECT_EQ(UserErrorMessage([&] { NumericColumn(ReadCsvTable(folder / "text.csv"), "b"); }),
            (folder / "text.csv").string() + ":2: column 'b': 'x' is not a finite number");
  WriteFile(folder / "nan.csv", "a,b\n1,2\n3,nan\n");
  EXPECT_EQ(UserErrorMessage([&] { NumericColumn(ReadCsvTable(folder / "nan.csv"), "b"); }),
            (folder / "nan.csv").string() + ":3: column 'b': 'nan' is not a finite number");
  EXPECT_NE(UserErrorMessage([&] { ReadCsvTable(folder / "none.csv"); }).find("cannot read"),
            std::string::npos);
}

// A train_ppo episodes.csv of `episodes` episodes that get better with training.
void WriteTrainingLog(const std::filesystem::path& path, int episodes, double skill) {
  std::string csv =
      "global_step,env,seed,reward,progress,mean_cte,steps,collision,goal,truncated\n";
  for (int k = 0; k < episodes; ++k) {
    const double learnt = skill * k / episodes;
    csv += std::to_string(600 * (k + 1)) + ",0,1,100," + std::to_string(0.5 + 0.45 * learnt) + "," +
           std::to_string(40 - 20 * learnt + k % 5) + "," + std::to_string(700 - 150 * learnt) +
           "," + (k % 9 == 0 ? "1" : "0") + ",1,0\n";
  }
  WriteFile(path, csv);
}

TEST(TrainingCurves, DrawsSeveralRuns) {
  const TemporaryFolder folder;
  WriteTrainingLog(folder / "a.csv", 400, 1.0);
  WriteTrainingLog(folder / "b.csv", 300, 0.6);
  const std::vector<TrainingRun> runs = {ReadTrainingRun("a", folder / "a.csv"),
                                         ReadTrainingRun("b", folder / "b.csv")};
  EXPECT_EQ(runs[1].collision.size(), 300U);
  EXPECT_DOUBLE_EQ(runs[0].global_step.back(), 240000.0);
  PlotTrainingCurves({RollingCurve(runs[0], 100), RollingCurve(runs[1], 100)}, "test runs",
                     "rolling mean and sd", folder / "curves.png");
  EXPECT_GT(std::filesystem::file_size(folder / "curves.png"), 10000U);
  PlotTrainingCurves({SeedCurve(runs, 100, 50)}, "two seeds", "range over seeds",
                     folder / "seeds.png");
  EXPECT_GT(std::filesystem::file_size(folder / "seeds.png"), 10000U);
  WriteFile(folder / "empty.csv", "global_step,progress,mean_cte,steps,collision\n");
  EXPECT_EQ(UserErrorMessage([&] { ReadTrainingRun("e", folder / "empty.csv"); }),
            (folder / "empty.csv").string() + ": no finished episode yet");
}

// Hand-made runs: seed a ends episodes at steps 10, 20, 30, 40 with collisions 1, 1, 0, 0; seed b
// at 15, 25, 35, 45, 55 with 0, 0, 0, 1, 1.
TrainingRun HandRun(const std::string& label, std::vector<double> steps,
                    std::vector<double> collisions) {
  TrainingRun run{label, std::move(steps), {}, {}, {}, std::move(collisions)};
  const std::size_t n = run.global_step.size();
  run.progress.assign(n, 0.5);
  run.cross_track_error.assign(n, 10.0);
  run.duration.assign(n, 100.0);
  return run;
}

TEST(TrainingCurves, RollingCurveShadesMeanMinusAndPlusSdNeverBelowZero) {
  const TrainingCurve curve = RollingCurve(HandRun("a", {10, 20, 30}, {1, 0, 0}), 2);
  ASSERT_EQ(curve.global_step, (std::vector<double>{10, 20, 30}));
  const std::vector<CurvePoint>& collisions = curve.panels[3];
  EXPECT_DOUBLE_EQ(collisions[1].mean, 0.5);
  EXPECT_DOUBLE_EQ(collisions[1].high, 0.5 + std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(collisions[1].low, 0.0);  // 0.5 - 0.707 clipped
  EXPECT_DOUBLE_EQ(collisions[2].mean, 0.0);
  EXPECT_DOUBLE_EQ(collisions[2].high, 0.0);
}

TEST(TrainingCurves, SeedCurveAveragesTheSeedsRollingMeansOnACommonGrid) {
  const std::vector<TrainingRun> seeds = {HandRun("cfg", {10, 20, 30, 40}, {1, 1, 0, 0}),
                                          HandRun("other", {15, 25, 35, 45, 55}, {0, 0, 0, 1, 1})};
  // Grid 0, 10, 20, 30, 40 (the last step both reached); window 2. At 0 and 10 seed b has no
  // episode yet: left out.
  const TrainingCurve curve = SeedCurve(seeds, 2, 5);
  EXPECT_EQ(curve.label, "cfg");
  ASSERT_EQ(curve.global_step, (std::vector<double>{20, 30, 40}));
  const std::vector<CurvePoint>& collisions = curve.panels[3];
  // At 20: a's rolling mean over {1, 1} = 1, b's over {0} = 0.
  EXPECT_DOUBLE_EQ(collisions[0].mean, 0.5);
  EXPECT_DOUBLE_EQ(collisions[0].low, 0.0);
  EXPECT_DOUBLE_EQ(collisions[0].high, 1.0);
  // At 30: a {1, 0} = 0.5, b {0, 0} = 0. At 40: a {0, 0} = 0, b {0, 0} = 0 (b's 45 is later).
  EXPECT_DOUBLE_EQ(collisions[1].mean, 0.25);
  EXPECT_DOUBLE_EQ(collisions[1].high, 0.5);
  EXPECT_DOUBLE_EQ(collisions[2].mean, 0.0);
  EXPECT_DOUBLE_EQ(curve.panels[1][2].mean, 10.0);  // constant cte
  EXPECT_THROW(SeedCurve({}, 2, 5), std::invalid_argument);
}

TEST(BetaSweep, TableSortedByBetaAndFigure) {
  const TemporaryFolder folder;
  std::vector<BetaSweepPoint> points;
  for (const double beta : {1.0, 0.0, 0.5}) {
    std::vector<EpisodeMetrics> episodes(10);
    for (int k = 0; k < 10; ++k) {
      episodes[k].progress = 0.9 + 0.01 * k * (1.0 - beta / 2);
      episodes[k].mean_abs_cte = 20 + k + beta;
      episodes[k].steps = 500 + 10 * k;
      episodes[k].collision = k == 0;
    }
    points.push_back({beta, SummariseModel("beta_" + std::to_string(beta), "p.pt", episodes)});
  }
  const std::string table = BetaSweepTable(points);
  EXPECT_LT(table.find("| 0 |"), table.find("| 0.5 |"));
  EXPECT_LT(table.find("| 0.5 |"), table.find("| 1 |"));
  EXPECT_NE(table.find("| 10.0 [-12.6, 32.6] |"), std::string::npos) << table;
  PlotBetaSweep(points, "sweep", folder / "sweep.png");
  EXPECT_GT(std::filesystem::file_size(folder / "sweep.png"), 10000U);
}

}  // namespace
}  // namespace colav

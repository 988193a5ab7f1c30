#include "eval/study/run_diagnostics.h"

#include <gtest/gtest.h>

#include "src/error.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::TemporaryFolder;
using testing_util::WriteFile;

constexpr char kUpdates[] = "global_step,n_updates,std,fps\n512,4,1.5,900\n1024,8,3.25,910\n";
// A run of 1,000 steps: its last tenth holds the episodes ending after step 900.
constexpr char kEpisodes[] =
    "global_step,env,seed,reward,progress,mean_cte,steps,collision,goal,truncated\n"
    "100,0,11,-1000,0.1,5,100,1,0,0\n"   // early: not counted
    "900,1,12,-1000,0.5,5,400,1,0,0\n"   // at the boundary: not counted
    "950,2,13,-1000,0.6,5,500,1,0,0\n"   // collided
    "990,3,14,-200,0.4,9,2001,0,0,1\n"   // timed out
    "998,4,15,300,0.99,7,600,0,1,0\n"    // reached the goal
    "1000,5,16,310,0.99,6,610,0,1,0\n";  // reached the goal

void WriteRun(const TemporaryFolder& run, const std::string& summary) {
  WriteFile(run / "summary.json", summary);
  WriteFile(run / "updates.csv", kUpdates);
  WriteFile(run / "episodes.csv", kEpisodes);
}

TEST(RunDiagnosticsTest, WallClockFinalStdAndTheLastTenthsTrainingEpisodes) {
  const TemporaryFolder run;
  WriteRun(run, R"({"finished": true, "wall_s": 3.0, "total_wall_s": 12.5})");
  const RunDiagnostics diagnostics = ReadRunDiagnostics(run.path());
  EXPECT_DOUBLE_EQ(diagnostics.wall_s, 12.5);  // every session, not the last one's 3 s
  EXPECT_DOUBLE_EQ(diagnostics.final_std, 3.25);
  EXPECT_EQ(diagnostics.late_episodes, 4);
  EXPECT_DOUBLE_EQ(diagnostics.late_collisions, 25.0);
  EXPECT_DOUBLE_EQ(diagnostics.late_time_outs, 25.0);
}

TEST(RunDiagnosticsTest, AMissingOrIncompleteFileIsAUserErrorNamingIt) {
  const TemporaryFolder run;
  WriteRun(run, R"({"finished": true, "wall_s": 3.0})");
  EXPECT_THROW(
      {
        try {
          ReadRunDiagnostics(run.path());
        } catch (const UserError& error) {
          EXPECT_NE(std::string(error.what()).find("summary.json: no number 'total_wall_s'"),
                    std::string::npos)
              << error.what();
          throw;
        }
      },
      UserError);
  WriteRun(run, R"({"total_wall_s": 1.0})");
  WriteFile(run / "updates.csv", "global_step,std\n");
  EXPECT_THROW(ReadRunDiagnostics(run.path()), UserError);
  WriteFile(run / "updates.csv", kUpdates);
  std::filesystem::remove(run / "episodes.csv");
  EXPECT_THROW(ReadRunDiagnostics(run.path()), UserError);
}

}  // namespace
}  // namespace colav

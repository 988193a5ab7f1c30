#include "eval/study/launcher_environment.h"

#include <gtest/gtest.h>

#include <map>

#include "src/error.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::UserErrorMessage;

// A launcher's environment made of the given variables only.
EnvironmentLookup Environment(const std::map<std::string, std::string>& variables) {
  return [variables](const std::string& name) -> std::optional<std::string> {
    const auto found = variables.find(name);
    if (found == variables.end()) return std::nullopt;
    return found->second;
  };
}

void ExpectShard(const StudyShard& shard, int index, int count, const std::string& source) {
  EXPECT_EQ(shard.index, index);
  EXPECT_EQ(shard.count, count);
  EXPECT_EQ(shard.source, source);
}

TEST(LauncherEnvironmentTest, ShardFlag) {
  ExpectShard(ParseShardFlag("0/1"), 0, 1, "--shard");
  ExpectShard(ParseShardFlag("2/3"), 2, 3, "--shard");
  for (const char* bad : {"", "3", "3/3", "4/3", "-1/2", "a/2", "1/0", "0/0", "1/2/3", " 1/2",
                          "1/2 ", "1/", "/2", "1.0/2", "99999999/100000000"}) {
    const std::string message = UserErrorMessage([&] { ParseShardFlag(bad); });
    EXPECT_NE(message.find(std::string("--shard ") + bad + ":"), std::string::npos)
        << "'" << bad << "': " << message;
  }
}

TEST(LauncherEnvironmentTest, EachLauncher) {
  ExpectShard(*ShardFromLauncher(
                  Environment({{"OMPI_COMM_WORLD_RANK", "2"}, {"OMPI_COMM_WORLD_SIZE", "4"}})),
              2, 4, "OMPI_COMM_WORLD_RANK/OMPI_COMM_WORLD_SIZE");
  ExpectShard(*ShardFromLauncher(Environment({{"PMI_RANK", "1"}, {"PMI_SIZE", "2"}})), 1, 2,
              "PMI_RANK/PMI_SIZE");
  ExpectShard(*ShardFromLauncher(Environment({{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "8"}})), 0, 8,
              "SLURM_PROCID/SLURM_NTASKS");
  EXPECT_FALSE(ShardFromLauncher(Environment({})));
}

TEST(LauncherEnvironmentTest, SlurmArrayTasksCountFromTheArraysFirstTask) {
  const std::string source = "SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT";
  // sbatch --array=0-3
  ExpectShard(*ShardFromLauncher(Environment({{"SLURM_ARRAY_TASK_ID", "3"},
                                              {"SLURM_ARRAY_TASK_COUNT", "4"},
                                              {"SLURM_ARRAY_TASK_MIN", "0"}})),
              3, 4, source);
  // sbatch --array=5-7: task 7 is the third.
  ExpectShard(*ShardFromLauncher(Environment({{"SLURM_ARRAY_TASK_ID", "7"},
                                              {"SLURM_ARRAY_TASK_COUNT", "3"},
                                              {"SLURM_ARRAY_TASK_MIN", "5"}})),
              2, 3, source);
  // sbatch --array=10-14:2 (10, 12, 14): task 14 is the third.
  ExpectShard(*ShardFromLauncher(Environment({{"SLURM_ARRAY_TASK_ID", "14"},
                                              {"SLURM_ARRAY_TASK_COUNT", "3"},
                                              {"SLURM_ARRAY_TASK_MIN", "10"},
                                              {"SLURM_ARRAY_TASK_STEP", "2"}})),
              2, 3, source);
  // An array inside an srun step: the array task is the share, not the step's task.
  ExpectShard(*ShardFromLauncher(Environment({{"SLURM_ARRAY_TASK_ID", "1"},
                                              {"SLURM_ARRAY_TASK_COUNT", "2"},
                                              {"SLURM_PROCID", "0"},
                                              {"SLURM_NTASKS", "1"}})),
              1, 2, source);
}

TEST(LauncherEnvironmentTest, TheFlagWinsThenMpirunThenSlurm) {
  const EnvironmentLookup both = Environment({{"OMPI_COMM_WORLD_RANK", "1"},
                                              {"OMPI_COMM_WORLD_SIZE", "3"},
                                              {"SLURM_PROCID", "0"},
                                              {"SLURM_NTASKS", "1"}});
  ExpectShard(ResolveShard(std::nullopt, both), 1, 3, "OMPI_COMM_WORLD_RANK/OMPI_COMM_WORLD_SIZE");
  ExpectShard(ResolveShard(std::string("0/2"), both), 0, 2, "--shard");
  ExpectShard(ResolveShard(std::nullopt, Environment({})), 0, 1, "none");
}

TEST(LauncherEnvironmentTest, BadLauncherValuesNameTheVariable) {
  const std::vector<std::pair<std::map<std::string, std::string>, std::string>> cases = {
      {{{"OMPI_COMM_WORLD_RANK", "x"}, {"OMPI_COMM_WORLD_SIZE", "2"}}, "OMPI_COMM_WORLD_RANK=x"},
      {{{"OMPI_COMM_WORLD_RANK", "1"}}, "OMPI_COMM_WORLD_SIZE: not set"},
      {{{"OMPI_COMM_WORLD_RANK", "2"}, {"OMPI_COMM_WORLD_SIZE", "2"}}, "OMPI_COMM_WORLD_RANK=2"},
      {{{"PMI_RANK", "-1"}, {"PMI_SIZE", "2"}}, "PMI_RANK=-1"},
      {{{"SLURM_ARRAY_TASK_ID", "3"},
        {"SLURM_ARRAY_TASK_COUNT", "2"},
        {"SLURM_ARRAY_TASK_MIN", "4"}},
       "SLURM_ARRAY_TASK_ID=3"},
      {{{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_COUNT", "0"}}, "SLURM_ARRAY_TASK_ID=3"},
      {{{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_COUNT", "two"}},
       "SLURM_ARRAY_TASK_COUNT=two"},
      {{{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", ""}}, "SLURM_NTASKS=: expects a whole number"},
      {{{"SLURM_PROCID", "0"}}, "SLURM_NTASKS: not set"},
  };
  for (const auto& [variables, expected] : cases) {
    const std::string message =
        UserErrorMessage([&] { ShardFromLauncher(Environment(variables)); });
    EXPECT_NE(message.find(expected), std::string::npos) << expected << ": " << message;
  }
}

TEST(LauncherEnvironmentTest, RanksAndCoresOnThisMachine) {
  EXPECT_EQ(RanksOnThisMachine(Environment({})), 1);
  EXPECT_EQ(RanksOnThisMachine(Environment({{"OMPI_COMM_WORLD_LOCAL_SIZE", "3"}})), 3);
  EXPECT_EQ(RanksOnThisMachine(Environment({{"MPI_LOCALNRANKS", "2"}})), 2);
  EXPECT_EQ(CoresOfThisRank(Environment({{"OMPI_COMM_WORLD_LOCAL_SIZE", "1000"}})), 1);
  EXPECT_EQ(CoresOfThisRank(Environment({{"SLURM_CPUS_PER_TASK", "1"}})), 1);
  EXPECT_GE(CoresOfThisRank(Environment({})), 1);
}

}  // namespace
}  // namespace colav

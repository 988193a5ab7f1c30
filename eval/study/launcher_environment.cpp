#include "eval/study/launcher_environment.h"

#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

#include "src/error.h"

namespace colav {
namespace {

// Far beyond any launch; keeps the arithmetic on rank numbers inside int.
constexpr long kMaxRanks = 1'000'000;

// A whole number 0 .. kMaxRanks written in plain digits, else nullopt.
std::optional<int> ParseCount(const std::string& text) {
  if (text.empty() || text.size() > 7 ||
      text.find_first_not_of("0123456789") != std::string::npos) {
    return std::nullopt;
  }
  const long value = std::strtol(text.c_str(), nullptr, 10);
  if (value > kMaxRanks) return std::nullopt;
  return static_cast<int>(value);
}

// The variable's value as a number; `fallback` when it is unset and a fallback is given.
int ReadNumber(const EnvironmentLookup& environment, const std::string& name,
               std::optional<int> fallback = std::nullopt) {
  const std::optional<std::string> text = environment(name);
  if (!text && fallback) return *fallback;
  if (!text) throw UserError(name + ": not set, though the launcher set the rank");
  const std::optional<int> value = ParseCount(*text);
  if (!value) {
    throw UserError(name + "=" + *text + ": expects a whole number (set by the launcher)");
  }
  return *value;
}

// rank/size variables of one launcher: both set, 0 <= rank < size.
std::optional<StudyShard> RankOfSize(const EnvironmentLookup& environment, const std::string& rank,
                                     const std::string& size) {
  if (!environment(rank)) return std::nullopt;
  const int index = ReadNumber(environment, rank);
  const int count = ReadNumber(environment, size);
  if (index >= count) {
    throw UserError(rank + "=" + std::to_string(index) + ": not below " + size + "=" +
                    std::to_string(count));
  }
  return StudyShard{index, count, rank + "/" + size};
}

// A Slurm job array: its tasks are numbered MIN, MIN+STEP, ... (e.g. --array=5-9 or 0-20:4);
// an irregular list (--array=1,4,9) wraps around the count, which only shifts starting offsets.
std::optional<StudyShard> SlurmArrayTask(const EnvironmentLookup& environment) {
  if (!environment("SLURM_ARRAY_TASK_ID")) return std::nullopt;
  const int id = ReadNumber(environment, "SLURM_ARRAY_TASK_ID");
  const int count = ReadNumber(environment, "SLURM_ARRAY_TASK_COUNT");
  const int min = ReadNumber(environment, "SLURM_ARRAY_TASK_MIN", 0);
  const int step = ReadNumber(environment, "SLURM_ARRAY_TASK_STEP", 1);
  if (count == 0 || step == 0 || id < min) {
    throw UserError("SLURM_ARRAY_TASK_ID=" + std::to_string(id) +
                    ": not a task of the array (min " + std::to_string(min) + ", step " +
                    std::to_string(step) + ", count " + std::to_string(count) + ")");
  }
  return StudyShard{(id - min) / step % count, count, "SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT"};
}

}  // namespace

EnvironmentLookup ProcessEnvironment() {
  return [](const std::string& name) -> std::optional<std::string> {
    const char* value = std::getenv(name.c_str());
    if (value == nullptr) return std::nullopt;
    return std::string(value);
  };
}

StudyShard ParseShardFlag(const std::string& text) {
  const std::size_t slash = text.find('/');
  const std::optional<int> index =
      slash == std::string::npos ? std::nullopt : ParseCount(text.substr(0, slash));
  const std::optional<int> count =
      slash == std::string::npos ? std::nullopt : ParseCount(text.substr(slash + 1));
  if (!index || !count) {
    throw UserError("--shard " + text + ": expects I/N, e.g. 0/4 (rank I of N, counted from 0)");
  }
  if (*count == 0 || *index >= *count) {
    throw UserError("--shard " + text + ": the rank I must be in 0 .. N-1");
  }
  return {*index, *count, "--shard"};
}

std::optional<StudyShard> ShardFromLauncher(const EnvironmentLookup& environment) {
  if (auto shard = RankOfSize(environment, "OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE")) {
    return shard;
  }
  if (auto shard = RankOfSize(environment, "PMI_RANK", "PMI_SIZE")) return shard;
  if (auto shard = SlurmArrayTask(environment)) return shard;
  return RankOfSize(environment, "SLURM_PROCID", "SLURM_NTASKS");
}

StudyShard ResolveShard(const std::optional<std::string>& flag,
                        const EnvironmentLookup& environment) {
  if (flag) return ParseShardFlag(*flag);
  return ShardFromLauncher(environment).value_or(StudyShard{});
}

int RanksOnThisMachine(const EnvironmentLookup& environment) {
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"}) {
    if (environment(name)) return std::max(1, ReadNumber(environment, name));
  }
  return 1;
}

int CoresOfThisRank(const EnvironmentLookup& environment) {
  const int machine = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  const int bound =
      sched_getaffinity(0, sizeof allowed, &allowed) == 0 ? CPU_COUNT(&allowed) : machine;
  if (environment("SLURM_CPUS_PER_TASK")) {  // Slurm without CPU binding (task/none) too
    return std::max(1, std::min(bound, ReadNumber(environment, "SLURM_CPUS_PER_TASK")));
  }
  if (bound < machine) return std::max(1, bound);
  return std::max(1, machine / RanksOnThisMachine(environment));
}

}  // namespace colav

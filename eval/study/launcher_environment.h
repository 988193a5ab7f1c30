// What the launcher tells a study rank: which share of the study it is (`--shard I/N`, or the
// variables of OpenMPI's mpirun, MPICH, a Slurm job array or srun) and how many ranks share its
// machine. Jobs are claimed dynamically (job_claims.h), so the share is not a fixed slice of the
// jobs: I is the rank's starting offset among the ready jobs, so that ranks begin on different
// jobs, and N the number of ranks of the launch.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace colav {

/// The value of an environment variable, or nullopt when unset.
using EnvironmentLookup = std::function<std::optional<std::string>(const std::string& name)>;

/// The process's own environment (getenv).
EnvironmentLookup ProcessEnvironment();

struct StudyShard {
  int index = 0;  ///< 0 .. count-1: where the rank starts in the ready jobs
  int count = 1;  ///< ranks of the launch
  /// Where the share came from, for the log: "--shard", "OMPI_COMM_WORLD_RANK/..." or "none".
  std::string source = "none";
};

/// `--shard I/N` (0 <= I < N); anything else is a UserError naming the flag and the value.
StudyShard ParseShardFlag(const std::string& text);

/// The share the launcher set, first found of: OpenMPI (OMPI_COMM_WORLD_RANK/SIZE), MPICH
/// (PMI_RANK/SIZE), a Slurm job array (SLURM_ARRAY_TASK_ID minus SLURM_ARRAY_TASK_MIN, over
/// SLURM_ARRAY_TASK_STEP, of SLURM_ARRAY_TASK_COUNT), srun (SLURM_PROCID/SLURM_NTASKS). nullopt
/// when none is set; a malformed value is a UserError naming the variable.
std::optional<StudyShard> ShardFromLauncher(const EnvironmentLookup& environment);

/// The explicit flag when given (it wins), else the launcher's share, else one rank of one.
StudyShard ResolveShard(const std::optional<std::string>& flag,
                        const EnvironmentLookup& environment);

/// Ranks of this launch on this machine (OMPI_COMM_WORLD_LOCAL_SIZE, MPI_LOCALNRANKS; else 1),
/// which share its cores.
int RanksOnThisMachine(const EnvironmentLookup& environment);

/// The cores this rank may use: Slurm's SLURM_CPUS_PER_TASK, else those its CPU affinity allows
/// when the launcher bound it (mpirun --bind-to), else the machine's cores shared with the other
/// ranks on it.
int CoresOfThisRank(const EnvironmentLookup& environment);

}  // namespace colav

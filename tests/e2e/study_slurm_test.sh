#!/usr/bin/env bash
# The study as a real Slurm job array: a single-node Slurm (munged, slurmctld, slurmd, started here
# on this machine with a configuration in WORK_DIR; slurm-wlm and munge installed when missing)
# runs `sbatch --array=0-1 scripts/cluster/slurm_array.sbatch` on the tiny study. Each task names
# its share, every job is started and finished exactly once among the tasks, one task writes the
# report, and it equals a one-rank run's (the wall-clock aside). The daemons are stopped at the end.
#   study_slurm_test.sh BIN_DIR WORK_DIR
set -euo pipefail
# shellcheck source=tests/e2e/cluster_test_lib.sh
source "$(dirname "$0")/cluster_test_lib.sh"
cluster_setup "study slurm test" "$1" "$2"

if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  [ "$(id -u)" -eq 0 ] || fail "Slurm is missing: apt-get install slurm-wlm munge (as root)"
  echo "installing slurm-wlm munge" >&2
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurm-wlm munge \
    >/dev/null 2>&1 || fail "cannot install slurm-wlm munge"
fi
[ "$(id -u)" -eq 0 ] || fail "the single-node Slurm of this test runs as root"

SLURM=$WORK/slurm
mkdir -p "$SLURM/state" "$SLURM/spool" "$SLURM/munge"
chmod 700 "$SLURM/munge"
head -c 1024 /dev/urandom >"$SLURM/munge/munge.key"
chmod 400 "$SLURM/munge/munge.key"
node=$(hostname -s)
cat >"$SLURM/slurm.conf" <<CONF
ClusterName=colavtest
SlurmctldHost=$node(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$SLURM/munge/munge.sock
CredType=cred/munge
SlurmctldPort=16817
SlurmdPort=16818
StateSaveLocation=$SLURM/state
SlurmdSpoolDir=$SLURM/spool
SlurmctldPidFile=$SLURM/slurmctld.pid
SlurmdPidFile=$SLURM/slurmd.pid
SlurmctldLogFile=$SLURM/slurmctld.log
SlurmdLogFile=$SLURM/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=4000 State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$SLURM/slurm.conf

# Stops the daemons this test started (by their pid files) and waits for them to end.
stop_slurm() {
  local pids=()
  for pid_file in "$SLURM/slurmd.pid" "$SLURM/slurmctld.pid" "$SLURM/munge/munged.pid"; do
    if [ -f "$pid_file" ]; then pids+=("$(cat "$pid_file")"); fi
  done
  [ ${#pids[@]} -gt 0 ] || return 0
  kill "${pids[@]}" 2>/dev/null || true
  for pid in "${pids[@]}"; do
    for _ in $(seq 100); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
  done
}
trap stop_slurm EXIT
munged --force --key-file="$SLURM/munge/munge.key" --socket="$SLURM/munge/munge.sock" \
  --pid-file="$SLURM/munge/munged.pid" --log-file="$SLURM/munge/munged.log" \
  --seed-file="$SLURM/munge/seed" || fail "munged did not start"
slurmctld -f "$SLURM_CONF" || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" || fail "slurmd did not start"

"$BIN/study" "$TINY" --out "$WORK/one" --jobs 1 >"$WORK/one.out" 2>"$WORK/one.err" ||
  { tail "$WORK/one.err"; fail "the one-rank run failed"; }
jobs_said started "$WORK/one.err" >"$WORK/jobs"

for _ in $(seq 100); do
  sinfo -h -o %T 2>/dev/null | grep -q idle && break
  sleep 0.2
done
sinfo -h -o %T | grep -q idle || { tail "$SLURM"/*.log; fail "the Slurm node is not up"; }
sbatch --wait --array=0-1 --cpus-per-task=1 --mem=1G --output="$WORK/task-%a.out" \
  --chdir="$WORK" --export=ALL,COLAV_BIN="$BIN" "$CLUSTER/slurm_array.sbatch" "$TINY" \
  "$WORK/run" >"$WORK/sbatch.out" 2>&1 || { cat "$WORK/sbatch.out" "$WORK"/task-*.out; fail "sbatch"; }

outputs=("$WORK"/task-*.out)
[ ${#outputs[@]} -eq 2 ] || fail "${#outputs[@]} task outputs, not 2"
for task in 0 1; do
  grep -q "^study: rank $task of 2 (from SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT)" \
    "$WORK/task-$task.out" || fail "task $task does not name its share"
done
diff <(jobs_said started "${outputs[@]}") "$WORK/jobs" >&2 || fail "not every job started once"
diff <(jobs_said finished "${outputs[@]}") "$WORK/jobs" >&2 || fail "not every job finished once"
[ "$(cat "${outputs[@]}" | grep -c '^study_wall_s: ')" -eq 1 ] || fail "not one report writer"
same_results "$WORK/one" "$WORK/run" || fail "the report differs from one rank's"
no_claims_left "$WORK/run" || fail "claims left behind"
echo "study slurm test passed"

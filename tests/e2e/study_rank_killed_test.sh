#!/usr/bin/env bash
# A rank that dies loses only its running job, and nothing runs twice. A study of 2 PPO runs long
# enough to be killed in, under two launchers:
# 1. A Slurm job array (tasks 4 and 5 of `sbatch --array=4-5`: scripts/cluster/slurm_array.sbatch
#    run with their SLURM_ARRAY_TASK_* variables): the rank running PPO seed 0 is killed (SIGKILL) once the run has a checkpoint.
#    Its program gets SIGTERM and checkpoints; the other rank takes the job over (same host: the
#    holder is gone), resumes it, completes the study and writes the report.
# 2. mpirun with 2 ranks: the rank running PPO seed 0 is killed the same way; mpirun ends the
#    other, and the same mpirun command again completes the study.
# Each time every job finishes exactly once (over all launches), the killed PPO run is resumed,
# not restarted, no claim is left, a plain rerun has nothing left to do, and the results equal a
# one-rank run's.
#   study_rank_killed_test.sh BIN_DIR WORK_DIR
set -euo pipefail
# shellcheck source=tests/e2e/cluster_test_lib.sh
source "$(dirname "$0")/cluster_test_lib.sh"
cluster_setup "study rank killed test" "$1" "$2"
sed -e 's/steps: 2048/steps: 90000/' "$TINY" >"$WORK/long.yaml"
ONLY=(--only baseline)
VICTIM_JOB=ppo/baseline/seed_0

# The pid of the rank holding VICTIM_JOB in study folder $1, once its program has checkpointed.
victim_rank() {
  local claim=$1/claims/${VICTIM_JOB//\//_}/1.claim
  for _ in $(seq 900); do
    if [ -f "$1/$VICTIM_JOB/training_state.pt" ] && [ -f "$claim" ]; then
      /usr/bin/python3 -c 'import json, sys
claim = json.load(open(sys.argv[1]))
sys.exit(1) if claim["worker"]["pid"] == 0 else print(claim["holder"]["pid"])' "$claim" &&
        return 0
    fi
    sleep 0.1
  done
  return 1
}

# check_completed RUN_DIR RANK_OUTPUTS...: after the kill and the completion.
check_completed() {
  local run=$1
  shift
  diff <(jobs_said finished "$@") "$WORK/jobs" >&2 || fail "$run: not every job finished once"
  jobs_said resumed "$@" | grep -qx "$VICTIM_JOB" || fail "$run: the killed run was not resumed"
  same_results "$WORK/one" "$run" || fail "$run: the report differs from one rank's"
  no_claims_left "$run" || fail "$run: claims left behind"
  "$BIN/study" "$WORK/long.yaml" --out "$run" "${ONLY[@]}" >/dev/null 2>"$run.rerun.err" || fail "$run: rerun"
  grep -q "^study: 0 jobs run, 6 skipped" "$run.rerun.err" || fail "$run: rerun had work left"
}

"$BIN/study" "$WORK/long.yaml" --out "$WORK/one" "${ONLY[@]}" --jobs 2 >"$WORK/one.out" 2>"$WORK/one.err" ||
  { tail "$WORK/one.err"; fail "the one-rank run failed"; }
jobs_said finished "$WORK/one.err" >"$WORK/jobs"
[ "$(wc -l <"$WORK/jobs")" -eq 6 ] || fail "the one-rank run did not run 6 jobs"

# 1. Slurm array tasks.
declare -A rank_pid
for task in 4 5; do
  COLAV_BIN=$BIN SLURM_ARRAY_JOB_ID=77 SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_MIN=4 \
    SLURM_ARRAY_TASK_COUNT=2 bash "$CLUSTER/slurm_array.sbatch" "$WORK/long.yaml" "$WORK/slurm" \
    "${ONLY[@]}" --jobs 1 >"$WORK/slurm.$task.out" 2>"$WORK/slurm.$task.err" &
  rank_pid[$task]=$!
done
victim=$(victim_rank "$WORK/slurm") || { kill "${rank_pid[@]}"; fail "slurm: $VICTIM_JOB never ran"; }
kill -KILL "$victim"
survivor=4
[ "${rank_pid[4]}" != "$victim" ] || survivor=5
wait "$victim" || true
wait "${rank_pid[$survivor]}" || { tail "$WORK/slurm.$survivor.err"; fail "slurm: the survivor failed"; }
grep -q "^study: rank $((survivor - 4)) of 2 (from SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT)" \
  "$WORK/slurm.$survivor.err" || fail "slurm: the rank does not name its share"
grep -q "^study: took over $VICTIM_JOB from .*:$victim\$" "$WORK/slurm.$survivor.err" ||
  { tail "$WORK/slurm.$survivor.err"; fail "slurm: the killed rank's job was not taken over"; }
grep -q '^study_wall_s: ' "$WORK/slurm.$survivor.out" || fail "slurm: the survivor wrote no report"
check_completed "$WORK/slurm" "$WORK"/slurm.*.err

# 2. mpirun: the launch ends with the killed rank; the same command completes the study.
mpirun_study 2 "$WORK/mpi.first" "$WORK/long.yaml" "$WORK/mpi" "${ONLY[@]}" --jobs 1 \
  >"$WORK/mpi.first.log" 2>&1 &
launcher=$!
victim=$(victim_rank "$WORK/mpi") || { kill "$launcher"; fail "mpirun: $VICTIM_JOB never ran"; }
kill -KILL "$victim"
wait "$launcher" && fail "mpirun: the launch with a killed rank succeeded"
mpirun_study 2 "$WORK/mpi.second" "$WORK/long.yaml" "$WORK/mpi" "${ONLY[@]}" --jobs 1 \
  >"$WORK/mpi.second.log" 2>&1 ||
  { tail -30 "$WORK/mpi.second.log"; fail "mpirun: the second launch failed"; }
check_completed "$WORK/mpi" "$WORK"/mpi.first/1/rank.*/stderr "$WORK"/mpi.second/1/rank.*/stderr
echo "study rank killed test passed"

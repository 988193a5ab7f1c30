#!/usr/bin/env bash
# A study shared by the ranks of a real mpirun (OpenMPI, through scripts/cluster/mpirun_study.sh)
# on this machine, with 2 and with 3 ranks: each rank says where its share came from, every job is started and finished exactly
# once among all ranks (none taken over), more than one rank runs jobs, exactly one writes the
# report, no claim is left, and REPORT.md and summary.json equal a one-rank run's (the wall-clock
# aside).
#   study_mpirun_test.sh BIN_DIR WORK_DIR
set -euo pipefail
# shellcheck source=tests/e2e/cluster_test_lib.sh
source "$(dirname "$0")/cluster_test_lib.sh"
cluster_setup "study mpirun test" "$1" "$2"

"$BIN/study" "$TINY" --out "$WORK/one" --jobs 1 >"$WORK/one.out" 2>"$WORK/one.err" ||
  { tail "$WORK/one.err"; fail "the one-rank run failed"; }
jobs_said started "$WORK/one.err" >"$WORK/jobs"
[ "$(wc -l <"$WORK/jobs")" -eq 10 ] || fail "the one-rank run did not run 10 jobs"

for ranks in 2 3; do
  run="$WORK/ranks$ranks"
  mpirun_study $ranks "$run.out" "$TINY" "$run" >"$run.log" 2>&1 ||
    { tail -30 "$run.log"; fail "$ranks ranks: mpirun failed"; }
  errors=("$run.out"/1/rank.*/stderr)
  [ ${#errors[@]} -eq $ranks ] || fail "$ranks ranks: ${#errors[@]} rank outputs"
  for ((rank = 0; rank < ranks; ++rank)); do
    grep -q "^study: rank $rank of $ranks (from OMPI_COMM_WORLD_RANK/OMPI_COMM_WORLD_SIZE)" \
      "$run.out/1/rank.$rank/stderr" || fail "$ranks ranks: rank $rank does not name its share"
  done
  diff <(jobs_said started "${errors[@]}") "$WORK/jobs" >&2 ||
    fail "$ranks ranks: not every job was started exactly once"
  diff <(jobs_said finished "${errors[@]}") "$WORK/jobs" >&2 ||
    fail "$ranks ranks: not every job finished exactly once"
  [ -z "$(jobs_said resumed "${errors[@]}")$(jobs_said 'took over' "${errors[@]}")" ] ||
    fail "$ranks ranks: a job was resumed or taken over"
  [ "$(grep -l "^study: [1-9][0-9]* jobs run" "${errors[@]}" | wc -l)" -ge 2 ] ||
    fail "$ranks ranks: one rank ran every job"
  [ "$(cat "$run.out"/1/rank.*/stdout | grep -c '^study_wall_s: ')" -eq 1 ] ||
    fail "$ranks ranks: not exactly one rank wrote the report"
  same_results "$WORK/one" "$run" || fail "$ranks ranks: the report differs from one rank's"
  no_claims_left "$run" || fail "$ranks ranks: claims left behind"
done
echo "study mpirun test passed"

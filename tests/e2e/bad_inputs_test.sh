#!/usr/bin/env bash
# Every program refuses bad input the same way (README "Programs"): exit status 2, exactly one
# line on stderr naming the bad input, and no output left behind. The cases are the rows of
# bad_inputs.tsv; each runs in an empty folder of its own, so anything it writes is seen.
#
#   bad_inputs_test.sh BIN_DIR WORK_DIR [TABLE]
#
# A row is: id <TAB> expected substring of the error line <TAB> fixture <TAB> command.
#   fixture  "-", or NAME=CONTENT: a file written into the case's folder first (CONTENT through
#            printf %b, so \n is a newline)
#   command  run by bash in the case's folder with $BIN (the programs) and $FIX (shared valid
#            inputs: actions.csv, scenario.yaml, data.h5, policy.pt, summary.json, episodes.csv,
#            nan_data.h5, neg_data.h5)
# Every case must fail while validating, before any work: each gets a few seconds at most.
set -u
BIN=$(cd "$1" && pwd)
WORK=$2
TABLE=${3:-$(dirname "$0")/bad_inputs.tsv}
PYTHON=${COLAV_PYTHON3:-/usr/bin/python3}
CASE_TIMEOUT=20
export BIN

rm -rf "$WORK"
mkdir -p "$WORK/fixtures" "$WORK/cases"
FIX=$(cd "$WORK/fixtures" && pwd)
export FIX
SOURCE_DIR=$(cd "$(dirname "$0")/../.." && pwd)

# Seconds since the $EPOCHREALTIME `$1`.
Elapsed() {
  awk -v start="$1" -v now="$EPOCHREALTIME" 'BEGIN { printf "%.1f", now - start }'
}

# The valid inputs the cases spoil one at a time.
make_fixtures() {
  cp "$SOURCE_DIR/configs/scenarios/head-on.yaml" "$FIX/scenario.yaml"
  printf 'a0,a1\n1,0\n1,0.5\n' >"$FIX/actions.csv"
  "$BIN/generate_dataset" --out "$FIX/data.h5" --sim-scans 30 --synthetic-scans 30 \
    >/dev/null 2>&1 || return 1
  "$BIN/train_ppo" --out "$FIX/ppo" --steps 64 --envs 1 --set ppo.n_steps=64 \
    --set ppo.batch_size=64 --set train.env_threads=1 >/dev/null 2>&1 || return 1
  cp "$FIX/ppo/policy.pt" "$FIX/policy.pt"
  cp "$FIX/ppo/episodes.csv" "$FIX/episodes.csv" 2>/dev/null ||
    printf 'global_step,progress,mean_cte,steps,collision\n10,0.5,3,10,0\n' >"$FIX/episodes.csv"
  "$BIN/evaluate" --policy "$FIX/policy.pt" --name good_policy --scenario "$FIX/scenario.yaml" \
    --set env.max_steps=5 --out "$FIX/eval" >/dev/null 2>&1 || return 1
  cp "$FIX/eval/summary.json" "$FIX/summary.json"
  # The dataset with one NaN range, and with one negative range.
  "$PYTHON" - "$FIX" <<'EOF' || return 1
import shutil, sys
import h5py
fix = sys.argv[1]
for name, value in (("nan_data.h5", float("nan")), ("neg_data.h5", -5.0)):
    shutil.copy(f"{fix}/data.h5", f"{fix}/{name}")
    with h5py.File(f"{fix}/{name}", "r+") as f:
        f["ranges"][3, 7] = value
EOF
}

start=$EPOCHREALTIME
if ! make_fixtures; then
  echo "FAIL: could not make the valid fixtures in $FIX"
  exit 1
fi
fixtures_s=$(Elapsed "$start")

# Runs one case; prints nothing when it passes, one FAIL line otherwise.
run_case() {
  local id=$1 expect=$2 fixture=$3 command=$4
  local dir="$WORK/cases/$id"
  mkdir -p "$dir"
  local fixture_name=""
  if [[ $fixture != - ]]; then
    fixture_name=${fixture%%=*}
    printf '%b' "${fixture#*=}" >"$dir/$fixture_name"
  fi
  (cd "$dir" && timeout "$CASE_TIMEOUT" bash -c "$command" >stdout.txt 2>stderr.txt)
  local status=$?
  local lines
  lines=$(wc -l <"$dir/stderr.txt")
  local left
  left=$(cd "$dir" && find . -mindepth 1 ! -name stdout.txt ! -name stderr.txt \
    ${fixture_name:+! -name "$fixture_name"} | head -3 | tr '\n' ' ')
  local problem=""
  if ((status == 124)); then
    problem="timed out after ${CASE_TIMEOUT} s"
  elif ((status != 2)); then
    problem="exit status $status, expected 2"
  elif ((lines != 1)); then
    problem="$lines lines on stderr, expected 1"
  elif ! grep -qF -- "$expect" "$dir/stderr.txt"; then
    problem="the error does not name '$expect'"
  elif [[ -n $left ]]; then
    problem="left behind: $left"
  fi
  if [[ -n $problem ]]; then
    echo "FAIL $id: $problem; stderr: $(head -c 300 "$dir/stderr.txt" | tr '\n' '|')"
  fi
}

# Runs the case of one table row (fields separated by tabs).
run_row() {
  local id expect fixture command
  IFS=$'\t' read -r id expect fixture command <<<"$1"
  run_case "$id" "$expect" "$fixture" "$command"
}
export -f run_case run_row
export WORK CASE_TIMEOUT

# Two cases at a time (the machine's cores).
cases_start=$EPOCHREALTIME
# shellcheck disable=SC2016  # $1 is expanded by the inner bash: it is the row
results=$(grep -v '^#' "$TABLE" | grep -v '^[[:space:]]*$' | tr '\n' '\0' |
  xargs -0 -n 1 -P 2 bash -c 'run_row "$1"' _)
cases_s=$(Elapsed "$cases_start")
total=$(grep -v '^#' "$TABLE" | grep -cv '^[[:space:]]*$')
failed=$(grep -c '^FAIL' <<<"$results")
[[ -n $results ]] && echo "$results"
ids=$(grep -v '^#' "$TABLE" | grep -v '^[[:space:]]*$' | cut -f1 | sort | uniq -d)
if [[ -n $ids ]]; then
  echo "FAIL: duplicate case ids: $ids"
  failed=$((failed + 1))
fi
printf 'bad inputs: %d of %d cases pass (fixtures %s s, cases %s s)\n' \
  $((total - failed)) "$total" "$fixtures_s" "$cases_s"
((failed == 0))

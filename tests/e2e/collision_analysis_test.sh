#!/usr/bin/env bash
# evaluate --analyse-collisions end to end: a policy that always goes full thrust ahead meets the
# head-on scenario's vessel; the analysis must find that collision on the step simulate reports
# for the same actions, name the vessel dead ahead with the warning time the closing speed gives,
# find it avoidable, and count it in collisions.md; a rerun with --overwrite removes that analysis.
#
# usage: collision_analysis_test.sh BIN_DIR WORK_DIR SOURCE_DIR
set -euo pipefail
bin=$1
work=$2
source=$3
python=${COLAV_PYTHON3:-/usr/bin/python3}
scenario="$source/configs/scenarios/head-on.yaml"
fail() { echo "collision analysis: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
"$python" "$source/tests/e2e/full_thrust_policy.py" "$work/full_thrust.pt"
{
  echo "a0,a1"
  for _ in $(seq 2000); do echo "1,0"; done
} >"$work/full_thrust.csv"
"$bin/simulate" --scenario "$scenario" --actions "$work/full_thrust.csv" --out "$work/trace.csv" \
  >/dev/null 2>&1
expected=$(awk -F, 'NR > 1 && $15 == 1 { print $1; exit }' "$work/trace.csv")
[ -n "$expected" ] || fail "no collision in simulate's head-on trace"

"$bin/evaluate" --policy "$work/full_thrust.pt" --name full_thrust --scenario "$scenario" \
  --analyse-collisions --out "$work/eval" >"$work/evaluate.log" 2>&1 ||
  fail "evaluate failed: $(tail -3 "$work/evaluate.log")"
rows=$(($(wc -l <"$work/eval/collisions.csv") - 1))
((rows == 1)) || fail "$rows collision rows, expected 1"
IFS=, read -r model name contact kind index speed bearing detection warning from_detection \
  before10 before30 before60 < <(sed -n 2p "$work/eval/collisions.csv")
[ "$model,$name,$kind,$index,$speed" = "full_thrust,head-on,vessel,0,0.500" ] ||
  fail "unexpected row: $(sed -n 2p "$work/eval/collisions.csv")"
((contact == expected)) || fail "contact on step $contact, simulate collides on step $expected"
awk -v b="$bearing" 'BEGIN { exit !(b > -5 && b < 5) }' || fail "bearing $bearing, expected ahead"
# In range (150 m) when the gap closes at 0.5 + 0.58 m/s to the vessel radius: 138 s of warning.
((warning == contact - detection && warning > 130 && warning < 145)) ||
  fail "in range from step $detection, $warning s before the contact; expected about 138 s"
[ "$from_detection,$before60" = "1,1" ] || fail "not found avoidable: $from_detection,$before60"
grep -q "^| full_thrust | 1 | 1 (100.0 %) | 1 (100.0 %) | 0 (0.0 %) |" "$work/eval/collisions.md" ||
  fail "collisions.md: $(cat "$work/eval/collisions.md")"

# A rerun with --overwrite and without the analysis leaves no analysis of the earlier run behind.
"$bin/evaluate" --policy "$work/full_thrust.pt" --name full_thrust --scenario "$scenario" \
  --overwrite --out "$work/eval" >"$work/evaluate2.log" 2>&1 ||
  fail "evaluate --overwrite failed: $(tail -3 "$work/evaluate2.log")"
[ -f "$work/eval/summary.json" ] || fail "no summary.json after evaluate --overwrite"
[ ! -e "$work/eval/collisions.csv" ] && [ ! -e "$work/eval/collisions.md" ] ||
  fail "evaluate --overwrite left the earlier run's collision analysis"
echo "collision analysis: the head-on collision on step $contact, as simulate reports it"

#!/usr/bin/env bash
# scripts/bare_path_scenarios.sh: evaluate's first test scenarios without obstacles. Each file is
# named as its test scenario, lists no obstacle, and starts the vessel exactly where the test
# scenario does (simulate's first two trace rows: the same state and path errors), with nothing
# in range.
#
# usage: bare_path_scenarios_test.sh BIN_DIR WORK_DIR SOURCE_DIR PYTHON_MODULE_DIR
set -euo pipefail
bin=$1
work=$2
source=$3
module=$4
fail() { echo "bare path scenarios: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
BIN=$bin PYTHON_MODULE_DIR=$module bash "$source/scripts/bare_path_scenarios.sh" "$work/bare" 3 1 \
  >/dev/null
mapfile -t seeds < <(PYTHONPATH=$module /usr/bin/python3 -c \
  "import colav; print(*colav.evaluation_scenario_seeds(3, 1), sep='\n')")
printf 'a0,a1\n1,0\n' >"$work/step.csv"
for k in 0 1 2; do
  file="$work/bare/bare-00$k.yaml"
  [ -f "$file" ] || fail "no $file"
  grep -q "^name: bare-00$k$" "$file" || fail "$file is not named bare-00$k"
  ! grep -q "obstacles" "$file" || fail "$file lists obstacles"
  "$bin/simulate" --scenario "$file" --actions "$work/step.csv" --out "$work/bare.csv" >/dev/null
  "$bin/simulate" --training-seed "${seeds[$k]}" --actions "$work/step.csv" \
    --out "$work/test.csv" >/dev/null
  # step,x,y,psi,u,v,r,cte,heading_error,look_ahead_heading_error,progress: columns 1-11
  cmp -s <(cut -d, -f1-11 "$work/bare.csv") <(cut -d, -f1-11 "$work/test.csv") ||
    fail "bare-00$k does not start as test-00$k"
  seen=$(awk -F, 'NR > 1 { for (i = 16; i <= NF; ++i) if ($i != 150) n++ } END { print n + 0 }' \
    "$work/bare.csv")
  ((seen == 0)) || fail "bare-00$k: $seen ranges under 150 m"
done
echo "bare path scenarios: 3 files as their test scenarios, no obstacles"

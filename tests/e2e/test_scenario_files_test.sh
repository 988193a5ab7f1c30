#!/usr/bin/env bash
# scripts/test_scenario_files.sh: evaluate's first test scenarios as files with all, none or one
# kind of their obstacles. Each file is named as its test scenario, keeps exactly the obstacles
# asked for, and starts the vessel exactly where the test scenario does (simulate's first two
# trace rows: the same state and path errors); with all obstacles the whole trace is the test
# scenario's, and without any nothing is in range. evaluate on the files draws one figure per
# model for each file, or for the first --file-figures of them.
#
# usage: test_scenario_files_test.sh BIN_DIR WORK_DIR SOURCE_DIR PYTHON_MODULE_DIR
set -euo pipefail
bin=$1
work=$2
source=$3
module=$4
fail() { echo "test scenario files: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
mapfile -t seeds < <(PYTHONPATH=$module /usr/bin/python3 -c \
  "import colav; print(*colav.evaluation_scenario_seeds(3, 1), sep='\n')")
printf 'a0,a1\n1,0\n' >"$work/step.csv"
# KEEP, file prefix, the lists the files keep (| separated), the trace columns that must match
for row in "all test static_obstacles|dynamic_obstacles 1-" "none bare - 1-11" \
  "static static static_obstacles 1-11" "dynamic dynamic dynamic_obstacles 1-11"; do
  read -r keep prefix lists columns <<<"$row"
  BIN=$bin PYTHON_MODULE_DIR=$module bash "$source/scripts/test_scenario_files.sh" \
    "$work/$keep" "$keep" 3 1 >/dev/null
  for k in 0 1 2; do
    file="$work/$keep/$prefix-00$k.yaml"
    [ -f "$file" ] || fail "no $file"
    grep -q "^name: $prefix-00$k$" "$file" || fail "$file is not named $prefix-00$k"
    kept=$({ grep -o '^[a-z_]*obstacles' "$file" || true; } | paste -sd'|' -)
    [ "${kept:--}" = "$lists" ] || fail "$file keeps '${kept}', expected '$lists'"
    "$bin/simulate" --scenario "$file" --actions "$work/step.csv" --out "$work/file.csv" >/dev/null
    "$bin/simulate" --training-seed "${seeds[$k]}" --actions "$work/step.csv" \
      --out "$work/test.csv" >/dev/null
    # 1-11: step,x,y,psi,u,v,r,cte,heading_error,look_ahead_heading_error,progress
    cmp -s <(cut -d, -f"$columns" "$work/file.csv") <(cut -d, -f"$columns" "$work/test.csv") ||
      fail "$prefix-00$k does not start as test-00$k"
  done
done
"$bin/simulate" --scenario "$work/none/bare-000.yaml" --actions "$work/step.csv" \
  --out "$work/bare.csv" >/dev/null
seen=$(awk -F, 'NR > 1 { for (i = 16; i <= NF; ++i) if ($i != 150) n++ } END { print n + 0 }' \
  "$work/bare.csv")
((seen == 0)) || fail "bare-000: $seen ranges under 150 m"

/usr/bin/python3 "$source/tests/e2e/full_thrust_policy.py" "$work/full_thrust.pt"
for cap in "" 2; do
  "$bin/evaluate" --policy "$work/full_thrust.pt" --policy "$work/full_thrust.pt" --name a \
    --name b --scenario "$work"/none/bare-00{0,1,2}.yaml ${cap:+--file-figures $cap} \
    --out "$work/evaluation$cap" >/dev/null 2>&1 || fail "evaluate on the bare files failed"
  drawn=$(find "$work/evaluation$cap/figures" -name '*.png' | wc -l)
  ((drawn == 2 * ${cap:-3})) || fail "--file-figures '${cap}': $drawn figures for 2 models"
done
echo "test scenario files: 3 files of each kind, as their test scenarios; figures capped"

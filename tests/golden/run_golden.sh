#!/usr/bin/env bash
# Replays every golden case with `simulate` and checks the trace with compare.py.
# Usage: run_golden.sh SIMULATE GOLDEN_DIR
set -u
simulate=$1
golden=$2
python=${PYTHON3:-python3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
total=0
failed=0
for scenario in "$golden"/*/*.scenario.yaml; do
  [ -f "$scenario" ] || continue
  case=${scenario%.scenario.yaml}
  name=$(basename "$case")
  total=$((total + 1))
  # One trace path for every case: simulate must replace the file it wrote before (interfaces.md).
  if "$simulate" --scenario "$scenario" --actions "$case.actions.csv" --out "$out/trace.csv" &&
     "$python" "$golden/compare.py" "$case.trace.csv" "$out/trace.csv" > "$out/$name.cmp" 2>&1; then
    echo "PASS $name"
  else
    failed=$((failed + 1))
    echo "FAIL $name"
    cat "$out/$name.cmp" 2>/dev/null | tail -n 25
  fi
done
echo "golden traces: $((total - failed)) of $total pass"
[ "$total" -gt 0 ] && [ "$failed" -eq 0 ]

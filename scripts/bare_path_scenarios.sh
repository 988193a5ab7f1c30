#!/usr/bin/env bash
# evaluate's test scenarios with every obstacle removed: the first N of master seed SEED as
# scenario files OUT/bare-KKK.yaml (KKK as in test-KKK), the same path and start with nothing to
# avoid. Policies evaluated on them (evaluate --scenario OUT/bare-*.yaml) show how closely each
# follows the bare path, the floor under its cross-track error (README, "What the cross-track
# error is made of").
# usage: scripts/bare_path_scenarios.sh OUT [N (1000)] [SEED (1)]
#   after scripts/build.sh; BIN (build/bin) and PYTHON_MODULE_DIR (build/python) may point elsewhere.
set -euo pipefail
out=$1
count=${2:-1000}
seed=${3:-1}
bin=${BIN:-build/bin}
module=${PYTHON_MODULE_DIR:-build/python}
mkdir -p "$out"
printf 'a0,a1\n0,0\n' >"$out/.one_step.csv"
PYTHONPATH=$module /usr/bin/python3 -c \
  "import colav; print(*colav.evaluation_scenario_seeds($count, $seed), sep='\n')" >"$out/.seeds"
k=0
while read -r world_seed; do
  name=$(printf 'bare-%03d' "$k")
  "$bin/simulate" --training-seed "$world_seed" --save-scenario "$out/$name.yaml" \
    --actions "$out/.one_step.csv" --out "$out/.trace.csv" >/dev/null
  # simulate writes the obstacles last: static_obstacles, then dynamic_obstacles.
  sed -i -e "s/^name: .*/name: $name/" -e '/^static_obstacles:/,$d' "$out/$name.yaml"
  k=$((k + 1))
done <"$out/.seeds"
rm -f "$out/.one_step.csv" "$out/.trace.csv" "$out/.seeds"
echo "wrote $k scenario files to $out"

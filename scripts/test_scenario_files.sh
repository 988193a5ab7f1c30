#!/usr/bin/env bash
# evaluate's test scenarios as scenario files, with all, none or one kind of their obstacles:
# the first N of master seed SEED as OUT/PREFIX-KKK.yaml (KKK as in test-KKK), each with the test
# scenario's path and start. KEEP: all (PREFIX test), none (bare), static (static: the circles
# only) or dynamic (dynamic: the moving vessels only). Policies evaluated on them (evaluate
# --scenario OUT/*.yaml) show what each kind of obstacle costs them (docs/results.md, "What the
# cross-track error is made of").
# usage: scripts/test_scenario_files.sh OUT KEEP [N (1000)] [SEED (1)]
#   after scripts/build.sh; BIN (build/bin) and PYTHON_MODULE_DIR (build/python) may point elsewhere.
set -euo pipefail
if (($# < 2)); then
  echo "usage: scripts/test_scenario_files.sh OUT KEEP [N (1000)] [SEED (1)]; KEEP: all, none, static or dynamic" >&2
  exit 2
fi
out=$1
keep=$2
count=${3:-1000}
seed=${4:-1}
bin=${BIN:-build/bin}
module=${PYTHON_MODULE_DIR:-build/python}
# simulate writes the obstacles last: static_obstacles, then dynamic_obstacles.
case $keep in
  all) prefix=test drop='' ;;
  none) prefix=bare drop='/^static_obstacles:/,$d' ;;
  static) prefix=static drop='/^dynamic_obstacles:/,$d' ;;
  dynamic) prefix=dynamic drop='/^static_obstacles:/,/^dynamic_obstacles:/{/^dynamic_obstacles:/!d}' ;;
  *)
    echo "test_scenario_files.sh: KEEP must be all, none, static or dynamic, got '$keep'" >&2
    exit 2
    ;;
esac
mkdir -p "$out"
printf 'a0,a1\n0,0\n' >"$out/.one_step.csv"
PYTHONPATH=$module /usr/bin/python3 -c \
  "import colav; print(*colav.evaluation_scenario_seeds($count, $seed), sep='\n')" >"$out/.seeds"
k=0
while read -r world_seed; do
  name=$(printf '%s-%03d' "$prefix" "$k")
  "$bin/simulate" --training-seed "$world_seed" --save-scenario "$out/$name.yaml" \
    --actions "$out/.one_step.csv" --out "$out/.trace.csv" >/dev/null
  sed -i -e "s/^name: .*/name: $name/" ${drop:+-e "$drop"} "$out/$name.yaml"
  k=$((k + 1))
done <"$out/.seeds"
rm -f "$out/.one_step.csv" "$out/.trace.csv" "$out/.seeds"
echo "wrote $k scenario files to $out"

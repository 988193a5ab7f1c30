#!/usr/bin/env bash
# The README's main command: installs what is missing, builds, then runs the main job with
# built-in defaults into runs/quickstart/: a training world of the paper driven by a
# line-of-sight pilot, its trace and picture, and the simulator's speed.
# (The learning pipeline joins this script as its stages land.)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
out=${OUT:-runs/quickstart}
mkdir -p "$out"
seed=${SEED:-7}

# simulate replays fixed actions: full thrust with a gentle sine rudder shows the world and the
# sensing of the vessel.
actions="$out/actions.csv"
awk 'BEGIN { print "a0,a1"; for (k = 0; k < 600; ++k) printf "1,%.6f\n", 0.3 * sin(2 * 3.14159265 * k / 120) }' > "$actions"
build/bin/simulate --training-seed "$seed" --actions "$actions" --out "$out/trace.csv" \
  --plot "$out/scene.png" --save-scenario "$out/scenario.yaml"
for scenario in configs/scenarios/*.yaml; do
  name=$(basename "$scenario" .yaml)
  build/bin/simulate --scenario "$scenario" --actions "$actions" --out "$out/$name.trace.csv" \
    --plot "$out/$name.png"
done
build/bin/bench_env --seconds 2 | tee "$out/bench_env.txt"
echo "quickstart: outputs in $out (scene.png, trace.csv, scenario.yaml, one picture per named scenario)"

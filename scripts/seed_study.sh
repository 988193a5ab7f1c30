#!/usr/bin/env bash
# Training-seed spread of the PPO agents: after scripts/reproduce_paper.sh (whose runs are seed 0),
# trains shallow_locked and baseline with further seeds and evaluates all of them together on the
# shared test scenarios (paired). A single PPO run per model, as in the paper, varies by several
# points of progress and collision rate from seed to seed; this measures by how much.
#   SEEDS="1 2 3" scripts/seed_study.sh      (writes $OUT/seeds/, reuses $OUT/ppo/* as seed 0)
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${OUT:-runs/paper}
BIN=${BIN:-build/bin}
SEEDS=${SEEDS:-"1 2 3"}
ENCODER="$OUT/vae/shallow/seed_0/encoder.pt"
[ -f "$ENCODER" ] || { echo "seed_study: $ENCODER missing; run scripts/reproduce_paper.sh first" >&2; exit 1; }

train() {  # train NAME SEED FLAGS...
  local dir="$OUT/seeds/$1_s$2" seed=$2 name=$1
  shift 2
  if [ -f "$dir/summary.json" ]; then echo "seed_study: $name seed $seed done, skipped"; return; fi
  if [ -f "$dir/training_state.pt" ]; then "$BIN/train_ppo" --resume "$dir"; return; fi
  "$BIN/train_ppo" "$@" --seed "$seed" --out "$dir"
}

models=(--name shallow_locked_s0 --policy "$OUT/ppo/shallow_locked/policy.pt"
        --name baseline_s0 --policy "$OUT/ppo/baseline/policy.pt")
for seed in $SEEDS; do
  train shallow_locked "$seed" --extractor vae-shallow --encoder "$ENCODER" --locked
  train baseline "$seed" --extractor baseline
  models+=(--name "shallow_locked_s$seed" --policy "$OUT/seeds/shallow_locked_s$seed/policy.pt"
           --name "baseline_s$seed" --policy "$OUT/seeds/baseline_s$seed/policy.pt")
done
"$BIN/evaluate" "${models[@]}" --trajectories 0 --out "$OUT/seeds/eval"
echo "seed_study: $OUT/seeds/eval/summary.md"

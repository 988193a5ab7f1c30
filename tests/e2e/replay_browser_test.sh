#!/usr/bin/env bash
# Replay pages in a real browser. `simulate --replay` writes the head-on episode (full thrust
# into the oncoming vessel), headless Chromium opens it, and replay_browser_check.py compares the
# page's self-check (read from the DOM) and screenshots with the episode's trace. Then
# `evaluate --replay` with two tiny trained policies: the pages it chooses, both models in each.
#
# usage: replay_browser_test.sh BIN_DIR WORK_DIR SOURCE_DIR
set -euo pipefail
bin=$1
work=$2
source=$3
python=${COLAV_PYTHON3:-/usr/bin/python3}

if ! command -v chromium >/dev/null; then
  "$source/scripts/install_deps.sh"  # chromium is one of its packages
fi

rm -rf "$work"
mkdir -p "$work"
{
  echo "a0,a1"
  for _ in $(seq 600); do echo "1,0"; done
} >"$work/full_thrust.csv"
"$bin/simulate" --scenario "$source/configs/scenarios/head-on.yaml" --actions "$work/full_thrust.csv" \
  --out "$work/trace.csv" --replay "$work/replay.html"
collision_step=$(awk -F, 'NR > 1 && $15 == 1 { print $1; exit }' "$work/trace.csv")
[ -n "$collision_step" ] || { echo "no collision in the head-on episode" >&2; exit 1; }

# Each run gets a fresh profile; Chromium must not reach the network.
chrome() {
  local profile
  profile=$(mktemp -d "$work/profile.XXXXXX")
  timeout 60 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$profile" --window-size=1000,720 "$@" 2>>"$work/chromium.log"
}
page="file://$work/replay.html"
follow="#step=$collision_step&rays=0"
scene="#step=$collision_step&view=scene&rays=0"
chrome --dump-dom "$page" >"$work/start.html"
chrome --dump-dom "$page$follow" >"$work/collision.html"
chrome --screenshot="$work/collision.png" "$page$follow"
chrome --dump-dom "$page$scene" >"$work/scene.html"
chrome --screenshot="$work/scene.png" "$page$scene"
chrome --virtual-time-budget=2000 --dump-dom "$page#step=10&play=1" >"$work/playing.html"

"$python" "$source/tests/e2e/replay_browser_check.py" simulate "$work/trace.csv" "$work/start.html" \
  "$work/collision.html" "$work/collision.png" "$work/scene.html" "$work/scene.png" \
  "$work/playing.html"

for seed in 0 1; do
  "$bin/train_ppo" --out "$work/ppo$seed" --seed $seed --steps 64 --envs 1 --set ppo.n_steps=64 \
    --set ppo.batch_size=64 --set train.env_threads=1 >"$work/train_ppo$seed.log" 2>&1
done
"$bin/evaluate" --policy "$work/ppo0/policy.pt" --name first --policy "$work/ppo1/policy.pt" \
  --name second --episodes 12 --set env.max_steps=1000 --replay --replay-first 1 \
  --replay-collisions 2 --out "$work/eval" >"$work/evaluate.log" 2>&1
mkdir "$work/doms"
doms=()
for replay in "$work"/eval/replays/*.html; do
  doms+=("$work/doms/$(basename "$replay")")
  chrome --dump-dom "file://$replay" >"${doms[-1]}"
done
"$python" "$source/tests/e2e/replay_browser_check.py" evaluate "$work/eval/episodes.csv" 1 2 \
  "$work/eval/replays" "${doms[@]}"

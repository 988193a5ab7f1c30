#!/usr/bin/env bash
# End-to-end smoke test: scripts/reproduce_paper.sh at a tiny scale (tiny dataset, one short VAE,
# a few thousand PPO steps for two agents and a two-point beta sweep, evaluation on five test
# scenarios and the named scenario files), then checks that every output exists and is
# well-formed, and that a second run skips every stage.
#   smoke_test.sh BIN_DIR WORK_DIR
set -euo pipefail
BIN=$(cd "$1" && pwd)
WORK=$2
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$WORK"
mkdir -p "$WORK"
WORK=$(cd "$WORK" && pwd)
OUT="$WORK/run"

run_pipeline() {
  env OUT="$OUT" BIN="$BIN" SKIP_BUILD=1 TITLE="Smoke test" \
    SIM_SCANS=150 SYNTHETIC_SCANS=150 VAE_MODELS=shallow VAE_SEEDS=1 VAE_EPOCHS=2 VAE_FIGURES=0 \
    PPO_CONFIGS="shallow_locked baseline" PPO_STEPS=2048 PPO_ENVS=2 BETAS="0 1.0" EPISODES=5 \
    "$ROOT/scripts/reproduce_paper.sh"
}

fail() { echo "smoke test: $*" >&2; exit 1; }
require_file() { [ -s "$OUT/$1" ] || fail "missing or empty output $1"; }
require_png() {
  require_file "$1"
  [ "$(head -c 8 "$OUT/$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "$1 is not a PNG"
}

start=$SECONDS
run_pipeline >"$WORK/first.log" 2>&1 || { tail -30 "$WORK/first.log"; fail "pipeline failed"; }
echo "first run: $((SECONDS - start)) s"

require_file data/scans.h5
require_file vae/shallow/summary.json
require_file vae/shallow/seed_0/encoder.pt
for run in shallow_locked baseline shallow_locked_beta_0; do
  require_file "ppo/$run/policy.pt"
  require_file "ppo/$run/episodes.csv"
done
for dir in eval/test eval/scenarios eval/beta_sweep; do
  require_file "$dir/episodes.csv"
  require_file "$dir/summary.json"
  require_file "$dir/summary.md"
done
for png in eval/test/figures/test-000_shallow_locked.png eval/test/figures/test-000_baseline.png \
  eval/scenarios/figures/head-on_baseline.png eval/scenarios/figures/narrow-gap_shallow_locked.png \
  figures/beta_sweep.png figures/training_configurations.png figures/training_best_vs_baseline.png \
  figures/training_beta_sweep.png; do
  require_png "$png"
done
require_file REPORT.md

# Tables: exact header, one row per episode and model, 11 fields each; JSON with every model.
python3 - "$OUT" <<'PY' || fail "malformed tables"
import csv, glob, json, os, re, sys
out = sys.argv[1]
header = ["model", "scenario", "seed", "progress", "mean_cte", "steps", "collision", "goal",
          "truncated", "reward", "path_length"]
for name, models, episodes in [("test", 2, 5), ("scenarios", 2, None), ("beta_sweep", 2, 5)]:
    rows = list(csv.reader(open(f"{out}/eval/{name}/episodes.csv")))
    assert rows[0] == header, rows[0]
    body = rows[1:]
    assert all(len(r) == 11 for r in body)
    if episodes is not None:
        assert len(body) == models * episodes, (name, len(body))
    for r in body:
        assert 0 <= float(r[3]) <= 1.1 and float(r[4]) >= 0 and int(r[5]) >= 1
        assert r[6] in "01" and r[7] in "01" and r[8] in "01"
    summary = json.load(open(f"{out}/eval/{name}/summary.json"))
    assert len(summary["models"]) == models
    assert len(summary["paired_differences"]) == models * (models - 1) // 2
    for m in summary["models"]:
        for key in ("progress", "cross_track_error", "duration", "collision", "reward", "goal"):
            i = m["metrics"][key]
            assert i["low"] <= i["mean"] <= i["high"], (name, m["name"], key)
    assert "| metric |" in open(f"{out}/eval/{name}/summary.md").read()
# Every picture the report shows exists.
report = open(f"{out}/REPORT.md").read()
for image in re.findall(r"!\[[^\]]*\]\(([^)]+)\)", report):
    assert os.path.getsize(os.path.join(out, image)) > 0, image
for section in ("Wall-clock per stage", "VAE test error", "PPO training", "Test on the shared",
                "Named scenario files", "Beta sweep"):
    assert section in report, section
PY

# Resumed: nothing left to do.
timings_before=$(wc -l <"$OUT/timings.tsv")
run_pipeline >"$WORK/second.log" 2>&1 || { tail -30 "$WORK/second.log"; fail "second run failed"; }
[ "$(wc -l <"$OUT/timings.tsv")" = "$timings_before" ] || fail "the second run redid a stage"
grep -q "ppo shallow_locked: up to date, skipped" "$WORK/second.log" || fail "no skip message"
echo "smoke test passed ($((SECONDS - start)) s)"

#!/usr/bin/env bash
# The study runner end to end with the real programs at a tiny budget: a bad program key and an
# ensemble of runs that would observe differently are refused before any work; 2 PPO configurations
# x 2 seeds (one with a VAE) and 2 ensembles of one run of each run to a report (the test, the
# paper's and validation scenarios, each on its own master seed); a second invocation
# skips every job, and one whose study file changed is refused; --plan lists the jobs before and
# after, creating nothing; a study stopped by SIGTERM during a PPO run exits 130 and the same
# command then finishes it.
#   study_test.sh BIN_DIR WORK_DIR
set -euo pipefail
# shellcheck source=tests/e2e/study_test_lib.sh
source "$(dirname "$0")/study_test_lib.sh"
study_test_setup "study test" "$1" "$2"

cat >"$WORK/tiny.yaml" <<'YAML'
name: tiny
dataset: {dataset.sim_scans: 150, dataset.synthetic_scans: 150}
vaes:
  shallow: {model: shallow, seeds: 1, set: {training.epochs: 2, figures.enabled: false}}
ppo:
  seeds: 2
  steps: 2048
  set: {ppo.n_envs: 2, train.keep_checkpoints: false}
  configs:
    shallow_locked: {extractor: vae-shallow, vae: shallow, locked: true, steps: 3072}
    baseline: {extractor: baseline}
ensembles:
  pair: {members: [shallow_locked, baseline]}
evaluation: {episodes: 6, seed: 3, paper_episodes: 4, validation_episodes: 3, validation_seed: 5,
             goal: {progress: 60, cross_track_error: 40, collision: 20}}
YAML

# A bad key of a program is refused before any job runs, naming the job and the key.
sed -e 's/ppo.n_envs: 2/ppo.n_env: 2/' "$WORK/tiny.yaml" >"$WORK/bad.yaml"
study_refuses bad "job ppo/shallow_locked/seed_0: train_ppo: .*ppo.n_env" "$WORK/bad.yaml" \
  --out "$WORK/bad"
[ ! -e "$WORK/bad/data" ] || fail "a job ran before the study was checked"

# So is an ensemble of runs that would observe differently (ensemble_policy refuses them).
cat >"$WORK/mixed.yaml" <<'YAML'
ppo:
  seeds: 1
  steps: 2048
  configs:
    log: {extractor: baseline}
    linear: {extractor: baseline, set: {env.closeness: linear}}
ensembles:
  pair: {members: [log, linear]}
YAML
study_refuses mixed "ensembles.pair: the runs of log .* observe differently" "$WORK/mixed.yaml" \
  --out "$WORK/mixed"
[ ! -e "$WORK/mixed/data" ] || fail "a job ran before the ensemble was checked"

# --plan lists the jobs the command would run and creates nothing.
"$BIN/study" "$WORK/tiny.yaml" --out "$WORK/run" --plan >"$WORK/plan.out" || fail "--plan failed"
grep -q "^13 jobs: 0 complete, 13 to run or resume" "$WORK/plan.out" || fail "plan before the run"
grep -q "^to run .* ensembles/pair/seed_1 *ensemble_policy *ppo/shallow_locked/seed_1, " \
  "$WORK/plan.out" || { cat "$WORK/plan.out"; fail "ensemble job not planned"; }
[ ! -e "$WORK/run" ] || fail "--plan created the study folder"

"$BIN/study" "$WORK/tiny.yaml" --out "$WORK/run" --jobs 2 >"$WORK/first.out" 2>"$WORK/first.err" ||
  { tail -20 "$WORK/first.err"; fail "first run failed"; }
grep -q "^study_wall_s: " "$WORK/first.out" || fail "no study_wall_s line"
for file in REPORT.md summary.json data/scans.h5 vae/shallow/seed_0/encoder.pt \
  ppo/shallow_locked/seed_1/policy.pt ppo/baseline/seed_0/policy.pt ensembles/pair/seed_1/policy.pt \
  eval/study/episodes.csv eval/paper/episodes.csv eval/validation/episodes.csv \
  figures/study_models.png figures/paper_models.png figures/validation_models.png \
  figures/study_trade_off.png figures/paper_trade_off.png \
  figures/training_baseline.png figures/training_shallow_locked.png; do
  [ -s "$WORK/run/$file" ] || fail "missing $file"
done
grep -q "(figures/study_trade_off.png)" "$WORK/run/REPORT.md" || fail "trade-off figure not in the report"
grep -q "^## Validation, to choose on (not the test): 3 scenarios (master seed 5)$" \
  "$WORK/run/REPORT.md" || fail "no validation section in the report"
grep -q "^## Chosen on the validation scenarios$" "$WORK/run/REPORT.md" ||
  fail "no model chosen on the validation scenarios in the report"
grep -q "| model | over | progress | cte | collisions | return |" "$WORK/run/REPORT.md" ||
  fail "no return in the report's probability of improvement"
grep -q "| PPO runs of | wall-clock s | std at the end |" "$WORK/run/REPORT.md" ||
  fail "no table of how the runs ended"
grep -q "^- pair: 2 of \[shallow_locked, baseline\]$" "$WORK/run/REPORT.md" || fail "no ensembles"
grep -q "13 jobs run, 0 skipped" "$WORK/first.err" || { cat "$WORK/first.err"; fail "job count"; }
"$BIN/study" "$WORK/tiny.yaml" --out "$WORK/run" --plan | grep -q "^13 jobs: 13 complete, 0 to" ||
  fail "plan after the run"
/usr/bin/python3 - "$WORK/run/summary.json" <<'PY' || fail "malformed summary.json"
import csv, json, os, statistics, sys
s = json.load(open(sys.argv[1]))
for name, episodes, seed in (("study", 6, 3), ("paper", 4, 0), ("validation", 3, 5)):
    sset = s["scenario_sets"][name]
    assert sset["episodes"] == episodes and sset["seed"] == seed, (name, sset["seed"])
    models = {m["name"]: m for m in sset["models"]}
    assert set(models) == {"shallow_locked", "baseline", "pair"}, models.keys()
    for m in models.values():
        assert m["seeds"] == 2
        c = m["metrics"]["collision"]
        assert 0 <= c["low"] <= c["mean"] <= c["high"] <= 100
        assert c["interval"] == "bootstrap over seeds"
        assert 0 <= m["metrics"]["time_out"]["mean"] <= 100
        o = m["outcomes"]
        lost = sum(o[part]["progress_lost"] for part in ("collision", "time_out", "rest"))
        assert abs(lost - (100 - m["metrics"]["progress"]["mean"])) < 1e-6, (lost, m)
        # the return: the mean over seeds of the mean summed reward in eval/<set>/episodes.csv
        rows = list(csv.DictReader(open(f"{os.path.dirname(sys.argv[1])}/eval/{name}/episodes.csv")))
        seed_means = [statistics.fmean(float(r["reward"]) for r in rows
                                       if r["model"] == f'{m["name"]}.seed_{k}') for k in range(2)]
        assert abs(m["metrics"]["return"]["mean"] - statistics.fmean(seed_means)) < 1e-6, (seed_means, m)
    # What averaging changes: each pair's progress minus its two runs' mean, over the 2 pairs.
    rows = list(csv.DictReader(open(f"{os.path.dirname(sys.argv[1])}/eval/{name}/episodes.csv")))
    progress = lambda model: statistics.fmean(float(r["progress"]) for r in rows
                                              if r["model"] == model)
    gains = [100 * (progress(f"pair.seed_{k}") - (progress(f"shallow_locked.seed_{k}") +
                                                 progress(f"baseline.seed_{k}")) / 2)
             for k in range(2)]
    (gain,) = sset["ensemble_gains"]
    assert gain["ensemble"] == "pair" and gain["metrics"]["progress"]["n"] == 2, gain
    assert abs(gain["metrics"]["progress"]["mean"] - statistics.fmean(gains)) < 1e-6, (gains, gain)
    poi = sset["probability_of_improvement"]
    assert [(p["model"], p["over"]) for p in poi] == [("shallow_locked", "baseline"),
                                                      ("pair", "baseline")]
    assert 0 <= poi[0]["metrics"]["progress"]["probability"] <= 1
    assert all(0 <= p["progress_split"][k] <= 1 for p in poi for k in
               ("both_at_goal_share", "both_at_goal_probability", "elsewhere_probability")), poi
    # Progress to the finish: every goal counts 100 %; P over scenarios and seed pairs.
    finish = lambda model: [100.0 if r["goal"] == "1" else 100 * float(r["progress"])
                            for r in rows if r["model"] == model]
    ours = [finish(f"shallow_locked.seed_{k}") for k in range(2)]
    theirs = [finish(f"baseline.seed_{k}") for k in range(2)]
    wins = [(a[t] > b[t]) + 0.5 * (a[t] == b[t]) for a in ours for b in theirs
            for t in range(len(a))]
    to_finish = poi[0]["metrics"]["progress_to_finish"]
    assert abs(to_finish["probability"] - statistics.fmean(wins)) < 1e-9, (wins, to_finish)
    assert to_finish["low"] <= to_finish["probability"] <= to_finish["high"], to_finish
# The validation scenarios are other scenarios than the test's (another master seed).
paths = {name: [r["path_length"] for r in csv.DictReader(open(
    f"{os.path.dirname(sys.argv[1])}/eval/{name}/episodes.csv")) if r["model"] == "baseline.seed_0"]
    for name in ("study", "validation")}
assert paths["study"][:3] != paths["validation"], paths
# The goal: each model's shortfall from its means, and the model the validation scenarios choose
# (the smallest; ties to fewer networks, then to file order), with its shortfall on the test.
goal = {"progress": (60, 1), "cross_track_error": (40, -1), "collision": (20, -1)}
def shortfall(sset, model):
    means = {m["name"]: m["metrics"] for m in sset["models"]}[model]
    return sum(max(0.0, sign * (bound - means[k]["mean"])) for k, (bound, sign) in goal.items())
networks = {"shallow_locked": 1, "baseline": 1, "pair": 2}
for name in ("study", "validation"):
    sset = s["scenario_sets"][name]
    for row in sset["goal_shortfall"]:
        assert abs(row["total"] - shortfall(sset, row["model"])) < 1e-9, row
        assert row["networks"] == networks[row["model"]], row
validation = s["scenario_sets"]["validation"]
order = ["shallow_locked", "baseline", "pair"]
expected = min(order, key=lambda m: (round(shortfall(validation, m), 9), networks[m], order.index(m)))
chosen = s["chosen_on_validation"]
assert chosen["model"] == expected, (chosen, expected)
assert abs(chosen["test_shortfall"] - shortfall(s["scenario_sets"]["study"], expected)) < 1e-9
assert chosen["meets_goal_on_test"] == (chosen["test_shortfall"] == 0), chosen
assert s["config_steps"] == {"shallow_locked": 3072, "baseline": 2048}, s["config_steps"]
assert s["ensembles"] == {"pair": {"members": ["shallow_locked", "baseline"], "count": 2}}
# How each run ended: its seeds' wall-clock, final std and late training episodes.
assert {name: len(runs) for name, runs in s["runs"].items()} == {"shallow_locked": 2, "baseline": 2}
for run in (run for runs in s["runs"].values() for run in runs):
    assert run["wall_s"] > 0 and run["final_std"] > 0 and run["late_episodes"] >= 1, run
    assert 0 <= run["late_collisions"] <= 100 and 0 <= run["late_time_outs"] <= 100, run
PY
# A configuration's own steps reach its runs and the report.
grep -q "total_steps: 3072" "$WORK/run/ppo/shallow_locked/seed_1/config.yaml" &&
  grep -q "total_steps: 2048" "$WORK/run/ppo/baseline/seed_1/config.yaml" || fail "own steps"
grep -q "training seed(s) of 2048 steps (shallow_locked: 3072);" "$WORK/run/REPORT.md" ||
  fail "own steps not in the report"

study_skips_all 13 "$WORK/tiny.yaml" --out "$WORK/run"

# A study file changed after its runs finished is refused before any work, naming the setting;
# the finished runs are not reported as runs of the new file.
sed -e 's/^  steps: 2048/  steps: 2560/' "$WORK/tiny.yaml" >"$WORK/changed.yaml"
study_refuses changed "job ppo/baseline/seed_0: the finished run in $WORK/run/ppo/baseline/seed_0 has ppo.total_steps = 2048, the study asks for 2560" \
  "$WORK/changed.yaml" --out "$WORK/run"

# Stopped in the middle of a longer PPO run, then resumed by the same command.
sed -e 's/steps: 2048/steps: 400000/' "$WORK/tiny.yaml" >"$WORK/long.yaml"
study_stopped_once "$WORK/long/ppo/baseline/seed_0/training_state.pt" long1 "$WORK/long.yaml" \
  --out "$WORK/long" --only baseline --seeds 1 --jobs 1
grep -q '"finished": false' "$WORK/long/ppo/baseline/seed_0/summary.json" ||
  fail "the PPO run finished before the stop"
"$BIN/study" "$WORK/long.yaml" --out "$WORK/long" --only baseline --seeds 1 --jobs 1 \
  >"$WORK/long2.out" 2>"$WORK/long2.err" || { tail "$WORK/long2.err"; fail "resume failed"; }
grep -q "resumed ppo/baseline/seed_0" "$WORK/long2.err" || fail "the PPO run was not resumed"
[ -s "$WORK/long/REPORT.md" ] || fail "no report after the resume"
echo "study test passed"

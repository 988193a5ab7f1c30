#!/usr/bin/env bash
# Students in a study, end to end with the real programs at a tiny budget: a bad distill_policy
# option is refused before any work; a memory relieved by the baseline at a stall, distilled into
# one network per seed (build/bin/distill_policy), then fine-tuned by train_ppo from each student,
# is evaluated and reported with the runs; a rerun skips every job, and one whose options changed
# is refused; a study that gains a kind evaluates only the new models' episodes; a study stopped
# during a distillation exits 130 and the same command continues it from its state.
#   study_students_test.sh BIN_DIR WORK_DIR
set -euo pipefail
# shellcheck source=tests/e2e/study_test_lib.sh
source "$(dirname "$0")/study_test_lib.sh"
study_test_setup "study students test" "$1" "$2"

cat >"$WORK/tiny.yaml" <<'YAML'
name: tiny_students
dataset: {dataset.sim_scans: 150, dataset.synthetic_scans: 150}
ppo:
  seeds: 2
  steps: 8192
  set: {ppo.n_envs: 2, ppo.n_steps: 64, ppo.batch_size: 64, train.keep_checkpoints: false}
  configs:
    memory: {extractor: baseline, set: {policy.recurrent_size: 4}}
    baseline: {extractor: baseline}
ensembles:
  relieved: {members: [memory, baseline], stall_pace_mps: 0.1, stall_steps: 2}
students:
  taught:
    teacher: relieved
    start: memory
    options: {iterations: 2, steps: 16, worlds: 2, sequence: 8, batch: 4, epochs: 1, keep: 2}
fine_tunes:
  tuned:
    student: taught
    steps: 4096
    set: {policy.init_keeps_log_std: false, policy.log_std_init: -1.0}
evaluation: {episodes: 4, seed: 3, paper_episodes: 0}
YAML

# A bad option of distill_policy is refused before any job runs, naming the job and the option.
sed -e 's/iterations: 2,/iteration: 2,/' "$WORK/tiny.yaml" >"$WORK/bad.yaml"
study_refuses bad "job students/taught/seed_0: distill_policy: unrecognized arguments: --iteration 2" \
  "$WORK/bad.yaml" --out "$WORK/bad"
[ ! -e "$WORK/bad/ppo" ] || fail "a job ran before the study was checked"

"$BIN/study" "$WORK/tiny.yaml" --out "$WORK/run" --jobs 2 >"$WORK/first.out" 2>"$WORK/first.err" ||
  { tail -20 "$WORK/first.err"; fail "first run failed"; }
for k in 0 1; do
  [ -s "$WORK/run/students/taught/seed_$k/policy.pt" ] || fail "no student $k"
  [ ! -e "$WORK/run/students/taught/seed_$k/policy.pt.state" ] || fail "student $k left its state"
done
grep -q "^- taught: 2 of relieved starting from memory, with --iterations 2 .*; seconds of each distillation: [0-9]*, [0-9]*$" \
  "$WORK/run/REPORT.md" || { grep taught "$WORK/run/REPORT.md"; fail "no students in the report"; }
grep -q "^- tuned: 2 of taught, 4096 steps with the settings of memory and policy.init_keeps_log_std=false, policy.log_std_init=-1.0$" \
  "$WORK/run/REPORT.md" || { grep tuned "$WORK/run/REPORT.md"; fail "no fine-tunes in the report"; }
for k in 0 1; do
  [ -s "$WORK/run/fine_tunes/tuned/seed_$k/policy.pt" ] || fail "no fine-tune $k"
  grep -q "init: \"$WORK/run/students/taught/seed_$k/policy.pt\"" \
    "$WORK/run/fine_tunes/tuned/seed_$k/config.yaml" || fail "fine-tune $k did not start from its student"
done
[ -s "$WORK/run/figures/training_tuned.png" ] || fail "no training figure of the fine-tunes"
# the dataset, 4 PPO runs, 3 figures, 2 ensembles, 2 students, 2 fine-tunes, 1 evaluation
grep -q "15 jobs run, 0 skipped" "$WORK/first.err" || { cat "$WORK/first.err"; fail "job count"; }
"$COLAV_PYTHON3" - "$WORK/run" <<'PY' || fail "malformed summary.json or student summary"
import csv, json, sys
run = sys.argv[1]
s = json.load(open(f"{run}/summary.json"))
assert s["students"]["taught"]["teacher"] == "relieved", s["students"]
assert s["students"]["taught"]["count"] == 2 and len(s["students"]["taught"]["seconds"]) == 2
models = {m["name"]: m for m in s["scenario_sets"]["study"]["models"]}
assert set(models) == {"memory", "baseline", "relieved", "taught", "tuned"}, models.keys()
assert models["taught"]["seeds"] == 2 and models["tuned"]["seeds"] == 2
assert s["fine_tunes"]["tuned"]["start"] == "memory" and s["fine_tunes"]["tuned"]["steps"] == 4096
assert len(s["runs"]["tuned"]) == 2, s["runs"]
poi = [(p["model"], p["over"]) for p in s["scenario_sets"]["study"]["probability_of_improvement"]]
assert ("taught", "baseline") in poi, poi
rows = [r for r in csv.DictReader(open(f"{run}/eval/study/episodes.csv"))
        if r["model"] == "taught.seed_1"]
assert len(rows) == 4, rows
student = json.load(open(f"{run}/students/taught/seed_1/policy.pt.json"))
assert student["finished"] is True and len(student["iterations"]) == 2, student
assert student["settings"]["seed"] == 1 and student["settings"]["threads"] == 1, student
assert student["settings"]["teacher"].endswith("/ensembles/relieved/seed_1/policy.pt"), student
assert student["settings"]["init"].endswith("/ppo/memory/seed_1/policy.pt"), student
PY

study_skips_all 15 "$WORK/tiny.yaml" --out "$WORK/run"

# A study file whose options changed after its students finished is refused before any work.
sed -e 's/epochs: 1,/epochs: 2,/' "$WORK/tiny.yaml" >"$WORK/changed.yaml"
study_refuses changed "job students/taught/seed_0: the finished run in $WORK/run/students/taught/seed_0 has settings.epochs = 1, the study asks for 2" \
  "$WORK/changed.yaml" --out "$WORK/run"

# A study that gains a kind of fine-tune runs it (2 runs, a figure) and evaluates again, taking
# the other models' episodes from the evaluation before (evaluate --reuse), unchanged.
cp -r "$WORK/run" "$WORK/grown"
sed -n '/^evaluation:/q;p' "$WORK/tiny.yaml" >"$WORK/grown.yaml"
cat >>"$WORK/grown.yaml" <<'YAML'
  narrower:
    student: taught
    steps: 4096
    set: {policy.init_keeps_log_std: false, policy.log_std_init: -2.0}
YAML
grep "^evaluation:" "$WORK/tiny.yaml" >>"$WORK/grown.yaml"
"$BIN/study" "$WORK/grown.yaml" --out "$WORK/grown" >"$WORK/grown.out" 2>"$WORK/grown.err" ||
  { tail "$WORK/grown.err"; fail "the grown study failed"; }
grep -q "4 jobs run, 14 skipped" "$WORK/grown.err" || { cat "$WORK/grown.err"; fail "grown jobs"; }
grep -q -- "--reuse: the episodes of 10 of 12 model(s) taken from" \
  "$WORK/grown/eval/study/evaluate.log" || fail "the grown study ran every model again"
diff <(grep -v "^narrower" "$WORK/grown/eval/study/episodes.csv") \
  "$WORK/run/eval/study/episodes.csv" >/dev/null || fail "the taken episodes changed"

# Stopped during a longer distillation, then continued by the same command.
sed -e 's/iterations: 2,/iterations: 40,/' "$WORK/tiny.yaml" >"$WORK/long.yaml"
mkdir -p "$WORK/long"
cp -r "$WORK/run/ppo" "$WORK/run/ensembles" "$WORK/long/"
study_stopped_once "$WORK/long/students/taught/seed_0/policy.pt.state" long1 "$WORK/long.yaml" \
  --out "$WORK/long" --seeds 1 --jobs 1
grep -q '"finished": false' "$WORK/long/students/taught/seed_0/policy.pt.json" ||
  fail "the distillation finished before the stop"
"$BIN/study" "$WORK/long.yaml" --out "$WORK/long" --seeds 1 --jobs 1 \
  >"$WORK/long2.out" 2>"$WORK/long2.err" || { tail "$WORK/long2.err"; fail "resume failed"; }
grep -q "resumed students/taught/seed_0" "$WORK/long2.err" || fail "the student was not resumed"
grep -q "resuming after iteration" "$WORK/long/logs/students_taught_seed_0.log" ||
  fail "the distillation did not continue from its state"
"$COLAV_PYTHON3" - "$WORK/long/students/taught/seed_0/policy.pt.json" <<'PY' || fail "resumed summary"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["finished"] is True, s
assert [i["iteration"] for i in s["iterations"]] == list(range(1, 41)), s["iterations"]
PY
echo "study students test passed"

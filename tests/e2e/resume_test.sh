#!/usr/bin/env bash
# Exact resume (README "Reliability"): a train_ppo and a train_vae run interrupted by SIGINT,
# SIGTERM and SIGKILL at several points, each time resumed, ends with the files of the same run
# uninterrupted (timing columns aside). A clean stop exits with status 75; while a run is going, a
# second process on its folder is refused.
#
#   resume_test.sh BIN_DIR WORK_DIR
set -u
BIN=$(cd "$1" && pwd)
WORK=$2
PYTHON=${COLAV_PYTHON3:-/usr/bin/python3}
STOPPED=75
rm -rf "$WORK"
mkdir -p "$WORK"
cd "$WORK" || exit 1
failed=0
fail() {
  echo "FAIL: $*"
  failed=1
}

# Waits until the file $1 exists or the process $2 has ended.
wait_for() {
  while [[ ! -e $1 ]] && kill -0 "$2" 2>/dev/null; do sleep 0.01; done
}

# Waits until the file $1 has $2 lines matching $3 or the process $4 has ended.
wait_for_lines() {
  while (($(grep -c "$3" "$1" 2>/dev/null) < $2)) && kill -0 "$4" 2>/dev/null; do sleep 0.01; done
}

# interrupt SIGNAL MARKER DELAY COMMAND...: runs COMMAND, sends SIGNAL DELAY s after the file
# MARKER appears (with MARKER "LOG:N": after the N-th session of LOG has started training), and
# checks the exit status: 75 after SIGINT or SIGTERM, killed after SIGKILL.
interrupt() {
  local signal=$1 marker=$2 delay=$3
  shift 3
  "$@" >>interrupted.log 2>&1 &
  local pid=$!
  if [[ $marker == *:* ]]; then
    wait_for_lines "${marker%:*}" "${marker##*:}" "scans; shallow" "$pid"
  else
    wait_for "$marker" "$pid"
  fi
  sleep "$delay"
  kill -s "$signal" "$pid" 2>/dev/null
  local status=0 expected=$STOPPED
  { wait "$pid"; } 2>/dev/null || status=$?
  [[ $signal == KILL ]] && expected=137
  ((status == expected)) || fail "$* stopped by SIG$signal after $marker: status $status, expected $expected"
}

# same_columns FILE_A FILE_B COLUMNS: the CSVs agree in those columns (cut -f list).
same_columns() {
  cmp -s <(cut -d, -f"$3" "$1") <(cut -d, -f"$3" "$2") || fail "$2 differs from $1 (columns $3)"
}

same_bytes() {
  cmp -s "$1" "$2" || fail "$2 differs from $1"
}

# --- train_ppo: rollouts of 512 steps, checkpoints every 1,000 steps (inside rollouts), episodes
# of up to 300 steps in progress at every interruption.
PPO=("$BIN/train_ppo" --envs 2 --set ppo.n_steps=256 --set ppo.batch_size=64 --set ppo.n_epochs=2
  --steps 20480 --set train.checkpoint_interval=1000 --set train.keep_checkpoints=true
  --set env.max_steps=300 --set train.env_threads=1)
"${PPO[@]}" --out ppo_whole >/dev/null 2>&1 || fail "uninterrupted train_ppo run failed"
interrupt INT ppo_parts/checkpoints/policy_3000.pt 0.02 "${PPO[@]}" --out ppo_parts
interrupt TERM ppo_parts/checkpoints/policy_8000.pt 0.05 "$BIN/train_ppo" --resume ppo_parts
# While a run holds its folder (here stopped with SIGSTOP), a second process on it is refused,
# naming the holder; then the holder is killed.
"$BIN/train_ppo" --resume ppo_parts >/dev/null 2>&1 &
pid=$!
wait_for ppo_parts/checkpoints/policy_12000.pt "$pid"
kill -s STOP "$pid"
status=0
"$BIN/train_ppo" --resume ppo_parts >/dev/null 2>second.err || status=$?
grep -q "in use by train_ppo, pid $pid on host" second.err && ((status == 2)) ||
  fail "a second train_ppo on a held folder: status $status, $(head -c 200 second.err)"
kill -s KILL "$pid"
{ wait "$pid"; } 2>/dev/null
interrupt KILL ppo_parts/checkpoints/policy_16000.pt 0.03 "$BIN/train_ppo" --resume ppo_parts
"$BIN/train_ppo" --resume ppo_parts >/dev/null 2>&1 || fail "the last resume of train_ppo failed"

same_bytes ppo_whole/episodes.csv ppo_parts/episodes.csv
same_bytes ppo_whole/policy.pt ppo_parts/policy.pt
same_columns ppo_whole/updates.csv ppo_parts/updates.csv 1-10  # then fps, rollout_s, update_s
[[ $(ls ppo_whole/checkpoints) == "$(ls ppo_parts/checkpoints)" ]] ||
  fail "the resumed run's checkpoints are not the uninterrupted run's"
for checkpoint in ppo_whole/checkpoints/*; do
  same_bytes "$checkpoint" "ppo_parts/checkpoints/${checkpoint##*/}"
done
grep -q '"finished": true' ppo_parts/summary.json || fail "the resumed run did not finish"
if "$PYTHON" -c "import torch" 2>/dev/null; then
  "$PYTHON" - ppo_whole/training_state.pt ppo_parts/training_state.pt <<'PY' || fail "training_state.pt tensors differ"
import sys
import torch

def tensors(path):
    found = {}
    def walk(module, prefix):
        for name, tensor in module.named_parameters(recurse=False):
            found[prefix + name] = tensor
        for name, child in module.named_children():
            walk(child, prefix + name + ".")
    walk(torch.jit.load(path), "")
    found.pop("wall_s")  # training time
    return found

a, b = tensors(sys.argv[1]), tensors(sys.argv[2])
sys.exit(0 if a.keys() == b.keys() and all(torch.equal(a[k], b[k]) for k in a) else 1)
PY
fi

# A stop within the last rollout, after its steps pass ppo.total_steps but before its update, is a
# stop like any other: status 75, and the resumed run ends as the uninterrupted one (one rollout of
# 16,384 steps for a run of 1,000; the signal comes 20 ms after the checkpoint at step 1,000, with
# 15,000 steps of the rollout to go).
LAST=("$BIN/train_ppo" --envs 2 --set ppo.n_steps=8192 --set ppo.batch_size=512 --set ppo.n_epochs=1
  --steps 1000 --set train.checkpoint_interval=1000 --set train.keep_checkpoints=true
  --set env.max_steps=300 --set train.env_threads=1)
"${LAST[@]}" --out last_whole >/dev/null 2>&1 || fail "uninterrupted one-rollout train_ppo run failed"
interrupt TERM last_parts/checkpoints/policy_1000.pt 0.02 "${LAST[@]}" --out last_parts
"$BIN/train_ppo" --resume last_parts >/dev/null 2>&1 || fail "the resume of the one-rollout run failed"
same_bytes last_whole/episodes.csv last_parts/episodes.csv
same_bytes last_whole/policy.pt last_parts/policy.pt

# --- train_vae: 2 seeds of 12 epochs (about 0.05 s per epoch) on a small dataset. A clean stop ends
# the epoch in progress; a SIGKILL loses it. The SIGKILL comes 0.05 s into the third session, which
# has 10 epochs of seed 1 left: with fewer, the run could finish first (it did once, at 8 epochs
# and 0.3 s), and the last resume would meet a complete run folder.
"$BIN/generate_dataset" --out scans.h5 --sim-scans 2000 --synthetic-scans 2000 >/dev/null 2>&1 ||
  fail "generate_dataset failed"
VAE=("$BIN/train_vae" --data scans.h5 --seeds 2 --epochs 12 --set figures.enabled=false)
"${VAE[@]}" --out vae_whole >/dev/null 2>&1 || fail "uninterrupted train_vae run failed"
interrupt INT vae_parts/seed_0/losses.csv 0 "${VAE[@]}" --out vae_parts
interrupt TERM vae_parts/seed_0/encoder.pt 0.1 "${VAE[@]}" --out vae_parts
interrupt KILL vae_parts/train_vae.log:3 0.05 "${VAE[@]}" --out vae_parts
"${VAE[@]}" --out vae_parts >/dev/null 2>&1 || fail "the last resume of train_vae failed"
for seed in seed_0 seed_1; do
  same_columns "vae_whole/$seed/losses.csv" "vae_parts/$seed/losses.csv" 1-5  # then seconds
  same_bytes "vae_whole/$seed/encoder.pt" "vae_parts/$seed/encoder.pt"
  same_bytes "vae_whole/$seed/vae.pt" "vae_parts/$seed/vae.pt"
done
"$PYTHON" - vae_whole/summary.json vae_parts/summary.json <<'PY' || fail "train_vae summaries differ"
import json
import sys

def without_times(value):
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if "seconds" not in k}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value

a, b = (without_times(json.load(open(path))) for path in sys.argv[1:])
sys.exit(0 if a == b else 1)
PY

((failed == 0)) && echo "resume: interrupted runs of train_ppo and train_vae end as uninterrupted ones"
((failed == 0))

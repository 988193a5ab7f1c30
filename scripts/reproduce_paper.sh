#!/usr/bin/env bash
# The paper's whole study, one stage after another, writing $OUT/REPORT.md with every table and
# figure:
#   dataset -> VAEs (Shallow, Deep; 10 seeds, beta 1, latent 12) -> VAE figures (zero padding vs
#   CPTC-1D, 2-D latent densities for beta 0/1/5) -> PPO agents (shallow/deep x locked/unlocked and
#   the baseline) -> evaluation on the shared test scenarios and the named scenario files -> beta
#   sweep of the best architecture, locked -> training curves -> report.
#
# Resumable: a stage whose outputs exist (and are newer than its inputs) is skipped; an interrupted
# train_ppo run is resumed from its last checkpoint. Rerun the same command after a stop.
#
# Every setting can be overridden from the environment (scripts/quickstart.sh runs this script
# at a small scale), e.g.  PPO_STEPS=1000000 BETAS="" scripts/reproduce_paper.sh
set -euo pipefail
cd "$(dirname "$0")/.."

OUT=${OUT:-runs/paper}
BIN=${BIN:-build/bin}
TITLE=${TITLE:-"Reproduction of the paper's study"}
SKIP_BUILD=${SKIP_BUILD:-0}
# Dataset (generate_dataset).
SIM_SCANS=${SIM_SCANS:-10000}
SYNTHETIC_SCANS=${SYNTHETIC_SCANS:-10000}
DATA_SEED=${DATA_SEED:-0}
# VAEs (train_vae, vae_figures).
VAE_MODELS=${VAE_MODELS:-"shallow deep"}
VAE_SEEDS=${VAE_SEEDS:-10}
VAE_EPOCHS=${VAE_EPOCHS:-25}
LATENT=${LATENT:-12}
VAE_FIGURES=${VAE_FIGURES:-1}
# PPO agents (train_ppo): <architecture>_<locked|unlocked> or baseline.
PPO_CONFIGS=${PPO_CONFIGS:-"shallow_locked shallow_unlocked deep_locked deep_unlocked baseline"}
PPO_STEPS=${PPO_STEPS:-3000000}
PPO_ENVS=${PPO_ENVS:-8}
PPO_SEED=${PPO_SEED:-0}
# Beta sweep of the best architecture, locked ("" = no sweep); BEST_ARCH=shallow|deep skips the
# automatic choice.
BETAS=${BETAS-"0 0.1 0.5 1.0 1.5 3.0"}
BEST_ARCH=${BEST_ARCH:-}
# Evaluation (evaluate).
EPISODES=${EPISODES:-100}
EVAL_SEED=${EVAL_SEED:-0}
# Throughput on this machine (2 cores), for the time estimate printed before starting.
RATE_SCANS_PER_S=${RATE_SCANS_PER_S:-3000}
RATE_VAE_MS_PER_EPOCH_10K=${RATE_VAE_MS_PER_EPOCH_10K:-250}
RATE_PPO_STEPS_PER_S=${RATE_PPO_STEPS_PER_S:-30000}
RATE_EVAL_S_PER_MODEL=${RATE_EVAL_S_PER_MODEL:-10}

DATA="$OUT/data/scans.h5"
TIMINGS="$OUT/timings.tsv"
FIGURES="$OUT/figures"

# ---------------------------------------------------------------------------------------------
# Stage plumbing.

log() { printf '\n== %s\n' "$*"; }

# fresh OUTPUT INPUT...: OUTPUT exists and no INPUT is newer.
fresh() {
  local output=$1 input
  shift
  [ -e "$output" ] || return 1
  for input in "$@"; do
    [ "$input" -nt "$output" ] && return 1
  done
  return 0
}

# timed STAGE COMMAND...: runs COMMAND and appends its wall-clock seconds to $TIMINGS (also when
# it fails, so interrupted stages add up over resumed sessions).
timed() {
  local stage=$1 start=$SECONDS status=0
  shift
  log "$stage: $*"
  "$@" || status=$?
  printf '%s\t%s\n' "$stage" "$((SECONDS - start))" >>"$TIMINGS"
  return "$status"
}

skip() { log "$1: up to date, skipped"; }

json_field() {  # json_field FILE EXPRESSION (python, on `d`)
  python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2"
}

ppo_finished() { [ -f "$1/summary.json" ] && [ "$(json_field "$1/summary.json" 'd["finished"]')" = True ]; }

is_one() { awk -v b="$1" 'BEGIN { exit !(b == 1) }'; }

encoder_of() { echo "$OUT/vae/$1/seed_0/encoder.pt"; }

# ---------------------------------------------------------------------------------------------
# Stages.

stage_dataset() {
  if [ -e "$DATA" ]; then skip dataset; return; fi
  timed dataset "$BIN/generate_dataset" --out "$DATA" --sim-scans "$SIM_SCANS" \
    --synthetic-scans "$SYNTHETIC_SCANS" --seed "$DATA_SEED"
}

# train_vae_run NAME ARCHITECTURE BETA SEEDS
train_vae_run() {
  local dir="$OUT/vae/$1"
  if fresh "$dir/summary.json" "$DATA"; then skip "vae $1"; return; fi
  timed "vae $1" "$BIN/train_vae" --data "$DATA" --model "$2" --latent "$LATENT" --beta "$3" \
    --epochs "$VAE_EPOCHS" --seeds "$4" --out "$dir"
}

stage_vae() {
  local model
  for model in $VAE_MODELS; do train_vae_run "$model" "$model" 1 "$VAE_SEEDS"; done
}

stage_vae_figures() {
  [ "$VAE_FIGURES" = 1 ] || return 0
  if fresh "$OUT/vae/figures/latent_kde.png" "$DATA"; then skip "vae figures"; return; fi
  timed "vae figures" "$BIN/vae_figures" --data "$DATA" --epochs "$VAE_EPOCHS" \
    --out "$OUT/vae/figures"
}

# train_agent NAME EXTRACTOR [ENCODER LOCK_FLAG]: trains, or resumes, one PPO run.
train_agent() {
  local name=$1 extractor=$2 encoder=${3:-} lock=${4:-} dir="$OUT/ppo/$1"
  if ppo_finished "$dir" && { [ -z "$encoder" ] || fresh "$dir/policy.pt" "$encoder"; }; then
    skip "ppo $name"
    return
  fi
  if [ -e "$dir/training_state.pt" ] && [ -f "$dir/config.yaml" ] &&
    { [ -z "$encoder" ] || ! [ "$encoder" -nt "$dir/config.yaml" ]; }; then
    timed "ppo $name" "$BIN/train_ppo" --resume "$dir"
  else
    rm -rf "$dir"
    timed "ppo $name" "$BIN/train_ppo" --extractor "$extractor" ${encoder:+--encoder "$encoder"} \
      $lock --steps "$PPO_STEPS" --envs "$PPO_ENVS" --seed "$PPO_SEED" --out "$dir"
  fi
  ppo_finished "$dir" || { echo "ppo $name stopped before the end; rerun to resume" >&2; exit 1; }
}

stage_ppo() {
  local config architecture
  for config in $PPO_CONFIGS; do
    if [ "$config" = baseline ]; then
      train_agent baseline baseline
    else
      architecture=${config%_*}
      train_agent "$config" "vae-$architecture" "$(encoder_of "$architecture")" "--${config#*_}"
    fi
  done
}

# evaluate_models OUT_DIR EXTRA_FLAGS NAME=POLICY...: evaluates the models together (paired).
evaluate_models() {
  local dir=$1 extra=$2 arguments=() policies=() item
  shift 2
  for item in "$@"; do
    arguments+=(--name "${item%%=*}" --policy "${item#*=}")
    policies+=("${item#*=}")
  done
  if fresh "$dir/summary.json" "${policies[@]}"; then skip "evaluate $dir"; return; fi
  # shellcheck disable=SC2086  # EXTRA_FLAGS are separate words
  timed "evaluate $(basename "$dir")" "$BIN/evaluate" "${arguments[@]}" $extra --out "$dir"
}

main_models() {
  local config
  for config in $PPO_CONFIGS; do echo "$config=$OUT/ppo/$config/policy.pt"; done
}

stage_evaluate() {
  mapfile -t models < <(main_models)
  evaluate_models "$OUT/eval/test" "--episodes $EPISODES --seed $EVAL_SEED" "${models[@]}"
  evaluate_models "$OUT/eval/scenarios" "$(printf -- '--scenario %s ' configs/scenarios/*.yaml)" \
    "${models[@]}"
}

# The architecture whose locked agent did best on the test scenarios: highest progress minus
# collision rate (a collision forfeits the rest of the path).
best_architecture() {
  if [ -n "$BEST_ARCH" ]; then echo "$BEST_ARCH"; return; fi
  python3 - "$OUT/eval/test/summary.json" <<'PY'
import json, sys
models = {m["name"]: m["metrics"] for m in json.load(open(sys.argv[1]))["models"]}
score = {a: models[a + "_locked"]["progress"]["mean"] - models[a + "_locked"]["collision"]["mean"]
         for a in ("shallow", "deep") if a + "_locked" in models}
print(max(score, key=score.get) if score else "shallow")
PY
}

sweep_models() {
  local best=$1 beta
  for beta in $BETAS; do
    if is_one "$beta"; then
      echo "beta_$beta=$OUT/ppo/${best}_locked/policy.pt"
    else
      echo "beta_$beta=$OUT/ppo/${best}_locked_beta_$beta/policy.pt"
    fi
  done
}

stage_beta_sweep() {
  [ -n "$BETAS" ] || return 0
  local best beta points=()
  best=$(best_architecture)
  echo "$best" >"$OUT/best_architecture.txt"
  log "beta sweep of $best, locked: beta in $BETAS"
  for beta in $BETAS; do
    if is_one "$beta"; then
      [ -e "$(encoder_of "$best")" ] || train_vae_run "$best" "$best" 1 "$VAE_SEEDS"
      [ -e "$OUT/ppo/${best}_locked/policy.pt" ] ||
        train_agent "${best}_locked" "vae-$best" "$(encoder_of "$best")" --locked
    else
      train_vae_run "${best}_beta_$beta" "$best" "$beta" 1
      train_agent "${best}_locked_beta_$beta" "vae-$best" "$(encoder_of "${best}_beta_$beta")" --locked
    fi
    points+=(--model "beta_$beta=$beta")
  done
  mapfile -t models < <(sweep_models "$best")
  evaluate_models "$OUT/eval/beta_sweep" "--episodes $EPISODES --seed $EVAL_SEED --trajectories 0" \
    "${models[@]}"
  if ! fresh "$FIGURES/beta_sweep.png" "$OUT/eval/beta_sweep/summary.json"; then
    "$BIN/plot_beta_sweep" --summary "$OUT/eval/beta_sweep/summary.json" "${points[@]}" \
      --title "Beta sweep ($best, locked): test metrics against beta" \
      --out "$FIGURES/beta_sweep.png" --table "$OUT/eval/beta_sweep/beta_table.md"
  fi
}

# plot_runs PNG TITLE CONFIG...: training curves of the runs that exist.
plot_runs() {
  local png=$1 title=$2 config runs=()
  shift 2
  for config in "$@"; do
    [ -f "$OUT/ppo/$config/episodes.csv" ] && runs+=(--run "$config=$OUT/ppo/$config")
  done
  [ ${#runs[@]} -gt 0 ] || return 0
  "$BIN/plot_training" "${runs[@]}" --title "$title" --out "$png"
}

stage_training_curves() {
  local vae_configs=() config best
  for config in $PPO_CONFIGS; do [ "$config" = baseline ] || vae_configs+=("$config"); done
  plot_runs "$FIGURES/training_configurations.png" "Training, VAE feature extractors" \
    "${vae_configs[@]}"
  best=$(cat "$OUT/best_architecture.txt" 2>/dev/null || echo shallow)
  plot_runs "$FIGURES/training_best_vs_baseline.png" "Training, ${best} locked vs baseline" \
    "${best}_locked" baseline
  if [ -n "$BETAS" ]; then
    local sweep=() beta
    for beta in $BETAS; do
      if is_one "$beta"; then sweep+=("${best}_locked"); else sweep+=("${best}_locked_beta_$beta"); fi
    done
    plot_runs "$FIGURES/training_beta_sweep.png" "Training, beta sweep (${best}, locked)" "${sweep[@]}"
  fi
}

# ---------------------------------------------------------------------------------------------
# Expected time of the stages still to run.

estimate_seconds() {
  local total=0 model config beta n_vae=0 n_ppo=0 n_eval=0 train_scans
  [ -e "$DATA" ] || total=$((total + (SIM_SCANS + SYNTHETIC_SCANS) / RATE_SCANS_PER_S))
  for model in $VAE_MODELS; do [ -e "$OUT/vae/$model/summary.json" ] || n_vae=$((n_vae + VAE_SEEDS)); done
  for beta in $BETAS; do
    is_one "$beta" && continue
    [ -e "$OUT/vae/shallow_beta_$beta/summary.json" ] || [ -e "$OUT/vae/deep_beta_$beta/summary.json" ] ||
      n_vae=$((n_vae + 1))
    ppo_finished "$OUT/ppo/shallow_locked_beta_$beta" || ppo_finished "$OUT/ppo/deep_locked_beta_$beta" ||
      n_ppo=$((n_ppo + 1))
  done
  [ "$VAE_FIGURES" = 1 ] && ! [ -e "$OUT/vae/figures/latent_kde.png" ] && n_vae=$((n_vae + 8))
  for config in $PPO_CONFIGS; do ppo_finished "$OUT/ppo/$config" || n_ppo=$((n_ppo + 1)); done
  n_eval=$(( $(wc -w <<<"$PPO_CONFIGS") + $(wc -w <<<"$BETAS") ))
  # Training split: 3 rotations of every scan, 70 % train, 80 % of that.
  train_scans=$(( (SIM_SCANS + SYNTHETIC_SCANS) * 3 * 56 / 100 ))
  total=$((total + n_vae * VAE_EPOCHS * RATE_VAE_MS_PER_EPOCH_10K * train_scans / 10000000))
  total=$((total + n_ppo * PPO_STEPS / RATE_PPO_STEPS_PER_S))
  total=$((total + n_eval * RATE_EVAL_S_PER_MODEL * EPISODES / 100))
  echo "$total"
}

# ---------------------------------------------------------------------------------------------
# Report.

write_report() {
  python3 - "$OUT" "$TITLE" "$EPISODES" "$PPO_STEPS" <<'PY'
import json, os, sys
from collections import OrderedDict

out, title, episodes, ppo_steps = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
lines = [f"# {title}", ""]

def rel(path):
    return os.path.relpath(path, out)

def exists(path):
    return os.path.exists(os.path.join(out, path))

def load(path):
    with open(os.path.join(out, path)) as f:
        return json.load(f)

def image(path, caption):
    if exists(path):
        lines.extend([f"![{caption}]({path})", ""])

def include(path):
    if exists(path):
        with open(os.path.join(out, path)) as f:
            lines.extend([f.read().strip(), ""])

def hms(seconds):
    seconds = int(round(seconds))
    return f"{seconds // 3600}:{seconds % 3600 // 60:02d}:{seconds % 60:02d}"

# Wall-clock per stage, summed over sessions.
timings = OrderedDict()
if exists("timings.tsv"):
    with open(os.path.join(out, "timings.tsv")) as f:
        for row in f:
            stage, seconds = row.rstrip("\n").split("\t")
            timings[stage] = timings.get(stage, 0) + int(seconds)
lines += ["## Wall-clock per stage", "", "| stage | wall-clock (h:mm:ss) |", "|---|---|"]
lines += [f"| {stage} | {hms(s)} |" for stage, s in timings.items()]
lines += [f"| **total** | **{hms(sum(timings.values()))}** |", ""]

# VAE.
paper_vae = {"shallow": "42.67 [42.58, 42.75]", "deep": "45.13 [40.72, 49.54]"}
vae_rows = []
for arch in ("shallow", "deep"):
    if exists(f"vae/{arch}/summary.json"):
        s = load(f"vae/{arch}/summary.json")
        e = s["test_error"]
        vae_rows.append(f"| {s['model']} | {e['mean']:.2f} [{e['low']:.2f}, {e['high']:.2f}] "
                        f"| {e['sd']:.3f} | {e['n']} | {s['seconds_per_seed']['mean']:.0f} s "
                        f"| {paper_vae[arch]} |")
if vae_rows:
    lines += ["## VAE test error", "",
              "Per test scan: BCE summed over the 180 rays + beta * KL summed over the latent "
              "(latent 12, beta 1), mean and Student-t 95 % CI over seeds.", "",
              "| model | test error [95 % CI] | sd | seeds | time per seed | paper |",
              "|---|---|---|---|---|---|", *vae_rows, ""]
    for arch in ("shallow", "deep"):
        image(f"vae/{arch}/training_curves.png", f"{arch} VAE training curves")
        image(f"vae/{arch}/reconstructions.png", f"{arch} VAE reconstructions")
if exists("vae/figures/padding_comparison.png") or exists("vae/figures/latent_kde.png"):
    lines += ["## VAE figures: zero padding vs CPTC-1D, latent densities", ""]
    image("vae/figures/padding_comparison.png", "zero padding vs CPTC-1D")
    image("vae/figures/latent_kde.png", "2-D latent densities, beta 0, 1, 5")

# PPO training.
runs = sorted(d for d in os.listdir(os.path.join(out, "ppo"))) if exists("ppo") else []
if runs:
    lines += ["## PPO training", "",
              "| run | steps | episodes | steps/s | wall-clock | last 100 episodes: progress, cte, collisions |",
              "|---|---|---|---|---|---|"]
    for run in runs:
        if not exists(f"ppo/{run}/summary.json"):
            continue
        s = load(f"ppo/{run}/summary.json")
        last = s.get("last_100_episodes", {})
        lines.append(f"| {run} | {s['global_step']:,} | {s['episodes']} | {s['steps_per_s']:.0f} "
                     f"| {hms(s['total_wall_s'])} | {100 * last.get('progress', 0):.1f} %, "
                     f"{last.get('mean_cte', 0):.1f} m, {100 * last.get('collision_rate', 0):.0f} % |")
    lines.append("")
    image("figures/training_configurations.png", "training curves of the VAE configurations")
    image("figures/training_best_vs_baseline.png", "training curves, best vs baseline")

# Test.
if exists("eval/test/summary.json"):
    lines += [f"## Test on the shared {episodes} scenarios", ""]
    include("eval/test/summary.md")
    models = {m["name"]: m for m in load("eval/test/summary.json")["models"]}
    paper = OrderedDict([("shallow_locked", ("96.7 [94.5, 98.9]", "18.7 [16.6, 20.9]", "547.2 [530.4, 563.9]", "5.0 [0.7, 9.4]")),
                         ("deep_locked", ("94.4 [90.8, 97.9]", "22.7 [18.6, 26.8]", "557.5 [526.2, 588.8]", "7.0 [1.9, 12.1]")),
                         ("baseline", ("96.4 [93.8, 99.1]", "21.4 [18.9, 24.0]", "557.6 [539.9, 575.2]", "4.0 [0.1, 7.9]"))])
    def cell(m, key, scale):
        i = m["metrics"][key]
        return f"{scale * i['mean']:.1f} [{scale * i['low']:.1f}, {scale * i['high']:.1f}]"
    rows = []
    for name, p in paper.items():
        if name in models:
            m = models[name]
            ours = (cell(m, "progress", 100), cell(m, "cross_track_error", 1),
                    cell(m, "duration", 1), cell(m, "collision", 100))
            rows.append(f"| {name} | ours | " + " | ".join(ours) + " |")
            rows.append(f"| | paper | " + " | ".join(p) + " |")
    if rows:
        lines += ["Next to the paper's table (progress %, cross-track error m, duration steps, "
                  "collisions %; mean [95 % CI]):", "",
                  "| model | source | progress | cte | duration | collisions |",
                  "|---|---|---|---|---|---|", *rows, ""]
    figures = sorted(f for f in os.listdir(os.path.join(out, "eval/test/figures"))) \
        if exists("eval/test/figures") else []
    scenarios = sorted({f.split("_", 1)[0] for f in figures})
    names = list(models)
    if scenarios:
        lines += ["### Trajectories", "",
                  "Each model from the test start and from perturbed starts; tracks coloured by "
                  "cumulative reward.", "",
                  "| scenario | " + " | ".join(names) + " |", "|---" * (len(names) + 1) + "|"]
        for scenario in scenarios:
            lines.append(f"| {scenario} | " + " | ".join(
                f"![{scenario} {n}](eval/test/figures/{scenario}_{n}.png)" for n in names) + " |")
        lines.append("")

if exists("eval/scenarios/summary.json"):
    lines += ["## Named scenario files (configs/scenarios)", ""]
    include("eval/scenarios/summary.md")
    names = [m["name"] for m in load("eval/scenarios/summary.json")["models"]]
    figures = sorted(os.listdir(os.path.join(out, "eval/scenarios/figures")))
    scenarios = sorted({f[: -len(f"_{n}.png")] for f in figures for n in names if f.endswith(f"_{n}.png")})
    lines += ["| scenario | " + " | ".join(names) + " |", "|---" * (len(names) + 1) + "|"]
    for scenario in scenarios:
        lines.append(f"| {scenario} | " + " | ".join(
            f"![{scenario} {n}](eval/scenarios/figures/{scenario}_{n}.png)" for n in names) + " |")
    lines.append("")

if exists("eval/beta_sweep/summary.json"):
    best = open(os.path.join(out, "best_architecture.txt")).read().strip()
    lines += [f"## Beta sweep ({best}, locked encoder)", ""]
    include("eval/beta_sweep/beta_table.md")
    image("figures/beta_sweep.png", "beta sweep")
    image("figures/training_beta_sweep.png", "training curves of the beta sweep")
    include("eval/beta_sweep/summary.md")

with open(os.path.join(out, "REPORT.md.tmp"), "w") as f:
    f.write("\n".join(lines) + "\n")
os.replace(os.path.join(out, "REPORT.md.tmp"), os.path.join(out, "REPORT.md"))
PY
}

# ---------------------------------------------------------------------------------------------

if [ "$SKIP_BUILD" != 1 ]; then scripts/build.sh; fi
mkdir -p "$OUT" "$FIGURES"
expected=$(estimate_seconds)
printf 'reproduce_paper: %s into %s\n' "$TITLE" "$OUT"
printf 'expected time of the remaining stages: about %d h %02d min (PPO at ~%s steps/s)\n' \
  $((expected / 3600)) $((expected % 3600 / 60)) "$RATE_PPO_STEPS_PER_S"

stage_dataset
stage_vae
stage_vae_figures
stage_ppo
stage_evaluate
stage_beta_sweep
stage_training_curves
write_report
log "report: $OUT/REPORT.md"

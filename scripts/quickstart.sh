#!/usr/bin/env bash
# The README's main command: installs what is missing, builds, then runs the paper's pipeline
# (scripts/reproduce_paper.sh) at a small scale into runs/quickstart: the paper's dataset, one
# Shallow VAE seed (instead of 10 of each model), the VAE figures, the paper's main comparison
# (PPO with the Shallow encoder locked vs the baseline CNN, 3,000,000 steps each; no unlocked or
# Deep agents, no beta sweep), evaluation on the shared test scenarios and the named scenario
# files, and runs/quickstart/REPORT.md with its figures. About 6 minutes after the build on 2 cores.
# Any setting of reproduce_paper.sh can be overridden from the environment, e.g.
#   PPO_STEPS=1000000 scripts/quickstart.sh
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
export SKIP_BUILD=1
export OUT=${OUT:-runs/quickstart}
export TITLE=${TITLE:-"Quickstart: the paper's pipeline at a small scale"}
export SIM_SCANS=${SIM_SCANS:-10000}
export SYNTHETIC_SCANS=${SYNTHETIC_SCANS:-10000}
export VAE_MODELS=${VAE_MODELS:-shallow}
export VAE_SEEDS=${VAE_SEEDS:-1}
export VAE_EPOCHS=${VAE_EPOCHS:-25}
export VAE_FIGURES=${VAE_FIGURES:-1}
export PPO_CONFIGS=${PPO_CONFIGS:-"shallow_locked baseline"}
export PPO_STEPS=${PPO_STEPS:-3000000}
export BETAS=${BETAS-}
exec scripts/reproduce_paper.sh

#!/usr/bin/env bash
# The paper's whole study at 5 training seeds per configuration (studies/paper.yaml) with the
# study runner into runs/paper: dataset, Shallow and Deep VAEs (10 seeds), the VAE figures, PPO
# with each encoder locked and unlocked, the baseline and the beta sweep, evaluated paired on
# 1,000 scenarios and the paper's 100 with the paper authors' agents, then REPORT.md. Resumable:
# rerun after a stop. Arguments go to the runner, e.g.  scripts/reproduce_paper.sh --jobs 1
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
exec build/bin/study studies/paper.yaml --out "${OUT:-runs/paper}" "$@"

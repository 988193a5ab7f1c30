#!/usr/bin/env bash
# The README's main command: installs what is missing, builds, then runs studies/quickstart.yaml
# with the study runner into runs/quickstart (REPORT.md, summary.json, figures/): the paper's
# dataset, one Shallow VAE seed, the VAE figures, PPO with the Shallow encoder locked against the
# baseline CNN (3,000,000 steps, one seed each), evaluated paired on 1,000 scenarios and the
# paper's 100 (the paper's table beside them; the authors' agents are in studies/paper.yaml).
# Resumable: rerun after a stop. Arguments go to the runner, e.g.  scripts/quickstart.sh --seeds 3
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
exec build/bin/study studies/quickstart.yaml --out "${OUT:-runs/quickstart}" "$@"

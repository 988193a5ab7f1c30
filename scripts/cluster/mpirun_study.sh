#!/usr/bin/env bash
# A study on several machines with OpenMPI's mpirun: one study rank per slot of HOSTFILE (one
# per machine: each rank runs one job per core of its machine). The ranks claim the study's jobs
# through the shared output folder (README, "Studies on a cluster"); mpirun only starts them.
#
#   scripts/cluster/mpirun_study.sh scripts/cluster/hostfile.example studies/paper.yaml \
#     /shared/runs/paper [study flags]
#
# Each machine needs the built programs at the same path (COLAV_BIN, default: this checkout's
# build/bin) and OUT on a file system all machines share. MPIRUN_FLAGS adds mpirun options
# (e.g. --allow-run-as-root --oversubscribe). If a rank dies mpirun ends the others, which stop
# their jobs cleanly: run the same command again to continue.
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: $0 HOSTFILE STUDY.yaml OUT [study flags]" >&2; exit 2; }
hostfile=$1
study_file=$(realpath "$2")
out=$(realpath -m "$3")
shift 3
bin=${COLAV_BIN:-$(cd "$(dirname "$0")/../.." && pwd)/build/bin}
# --bind-to none: a rank's jobs use all the cores of its machine, not the one mpirun would pin it to.
# shellcheck disable=SC2086  # MPIRUN_FLAGS is a list of options
exec mpirun --hostfile "$hostfile" --map-by node --bind-to none ${MPIRUN_FLAGS:-} \
  "$bin/study" "$study_file" --out "$out" "$@"

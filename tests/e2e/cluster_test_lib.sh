# shellcheck shell=bash
# Helpers of the cluster tests (study_mpirun_test.sh, study_rank_killed_test.sh), sourced. They
# launch ranks through scripts/cluster/, as a cluster's user would.
# Sets TEST_NAME, BIN, WORK, TINY (the tiny study file) and CLUSTER (scripts/cluster).

# shellcheck source=tests/e2e/study_test_lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/study_test_lib.sh"

# cluster_setup NAME BIN_DIR WORK_DIR: a fresh work folder; mpirun installed (openmpi-bin) if
# missing.
cluster_setup() {
  study_test_setup "$@"
  # shellcheck disable=SC2034  # for the scripts that source this file
  TINY="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/cluster_tiny_study.yaml"
  CLUSTER="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../scripts/cluster" && pwd)"
  if ! command -v mpirun >/dev/null; then
    [ "$(id -u)" -eq 0 ] || fail "mpirun is missing: apt-get install openmpi-bin (as root)"
    echo "installing openmpi-bin" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get install -y -qq --no-install-recommends openmpi-bin >/dev/null 2>&1 ||
      { apt-get update -qq && apt-get install -y -qq --no-install-recommends openmpi-bin >/dev/null; } ||
      fail "cannot install openmpi-bin"
  fi
}

# mpirun_study RANKS OUTPUTS STUDY.yaml OUT [study flags]: scripts/cluster/mpirun_study.sh with
# RANKS ranks on this machine (more than its cores; root, as CI runs, must be allowed), each
# rank's stdout and stderr in OUTPUTS/1/rank.<r>/.
mpirun_study() {
  local ranks=$1 outputs=$2
  shift 2
  echo "localhost slots=$ranks" >"$WORK/hostfile.$ranks"
  local flags="--oversubscribe --output-filename $outputs"
  [ "$(id -u)" -ne 0 ] || flags+=" --allow-run-as-root"
  MPIRUN_FLAGS=$flags COLAV_BIN=$BIN "$CLUSTER/mpirun_study.sh" "$WORK/hostfile.$ranks" "$@"
}

# The job ids a study's rank outputs name after `verb` ("started", "resumed", "took over").
jobs_said() {
  local verb=$1
  shift
  cat "$@" | sed -n "s/^study: $verb \([^ ]*\).*/\1/p" | sort
}

# same_results DIR_A DIR_B: the two studies' REPORT.md and summary.json are equal, the
# wall-clock (the study's and each run's) aside.
same_results() {
  /usr/bin/python3 - "$1" "$2" <<'PY'
import json, re, sys
def summary(folder):
    s = json.load(open(folder + "/summary.json"))
    s.pop("wall_s")
    for runs in s["runs"].values():
        for run in runs:
            run.pop("wall_s")
    return s
def report(folder):
    text = open(folder + "/REPORT.md").read()
    text = re.sub(r"wall-clock of the study \(every run of it\) \d+ s", "", text)
    # the runs table's second column: each seed's wall-clock
    return re.sub(r"^(\| [^|]+ \| )[\d, ]+( \| [^|]+ \| [^|]+ \| [^|]+ \|)$", r"\1\2", text,
                  flags=re.MULTILINE)
a, b = sys.argv[1:3]
sys.exit(0 if summary(a) == summary(b) and report(a) == report(b) else 1)
PY
}

# No claim is left behind once a study completed (every holder released its claims).
no_claims_left() {
  [ -z "$(find "$1/claims" -name '*.claim')" ]
}

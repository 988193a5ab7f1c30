# shellcheck shell=bash
# Helpers of the study tests (study_test.sh, study_students_test.sh, and through
# cluster_test_lib.sh the cluster tests), sourced.

fail() { echo "$TEST_NAME: $*" >&2; exit 1; }

# study_test_setup NAME BIN_DIR WORK_DIR: sets TEST_NAME, BIN (the programs) and WORK (the
# test's folder, made afresh).
study_test_setup() {
  TEST_NAME=$1
  BIN=$(cd "$2" && pwd)
  WORK=$3
  rm -rf "$WORK"
  mkdir -p "$WORK"
  WORK=$(cd "$WORK" && pwd)
}

# study_refuses NAME PATTERN STUDY_ARGS...: `study STUDY_ARGS` exits 2 with one line on stderr
# (kept in WORK/NAME.err) that matches the grep PATTERN.
study_refuses() {
  local name=$1 pattern=$2
  shift 2
  local status=0
  "$BIN/study" "$@" 2>"$WORK/$name.err" >/dev/null || status=$?
  if [ $status -ne 2 ] || [ "$(wc -l <"$WORK/$name.err")" -ne 1 ] ||
    ! grep -q -- "$pattern" "$WORK/$name.err"; then
    cat "$WORK/$name.err"
    fail "$name: exit status $status, or not one line matching $pattern"
  fi
}

# study_stopped_once FILE NAME STUDY_ARGS...: `study STUDY_ARGS` started in the background (its
# output in WORK/NAME.out and .err), stopped by SIGTERM once FILE exists; it must exit 130.
study_stopped_once() {
  local file=$1 name=$2
  shift 2
  "$BIN/study" "$@" >"$WORK/$name.out" 2>"$WORK/$name.err" &
  local pid=$!
  for _ in $(seq 600); do
    [ -f "$file" ] && break
    sleep 0.1
  done
  [ -f "$file" ] || { kill $pid; cat "$WORK/$name.err"; fail "$name: no $file"; }
  kill -TERM $pid
  local status=0
  wait $pid || status=$?
  [ $status -eq 130 ] || { cat "$WORK/$name.err"; fail "$name: stopped study exited $status"; }
}

# study_skips_all JOBS STUDY_ARGS...: `study STUDY_ARGS` again skips all JOBS jobs, complete.
study_skips_all() {
  local jobs=$1
  shift
  "$BIN/study" "$@" >"$WORK/again.out" 2>"$WORK/again.err" || fail "the rerun failed"
  grep -q "0 jobs run, $jobs skipped" "$WORK/again.err" || { cat "$WORK/again.err"; fail "not skipped"; }
}

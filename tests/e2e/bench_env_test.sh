#!/usr/bin/env bash
# bench_env end to end, briefly: every case prints a positive rate, the ceiling case and the share
# of it are there, and the headline lines of interfaces.md end the output (rates, not timings, are
# checked: a benchmark's speed is not a test's business).
#
# usage: bench_env_test.sh BIN_DIR WORK_DIR
set -euo pipefail
bin=$1
work=$2
fail() { echo "bench_env: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
"$bin/bench_env" --seconds 0.1 --rounds 2 --envs 4 --threads 2 --async-batch 2 >"$work/out.txt" ||
  fail "exited with $?"
out="$work/out.txt"
positive_rate() {  # a line starting with $1, then a rate in steps/s above 0
  grep -Eq "^$1 +[1-9][0-9]* steps/s" "$out" || fail "no positive rate for '$1' in: $(cat "$out")"
}
positive_rate "1 thread, random actions"
positive_rate "4 worlds on 1 thread, random actions"
positive_rate "4 worlds on 2 threads, random actions"
positive_rate "4 worlds in 2 independent threads \(ceiling\)"
positive_rate "4 worlds on 2 threads, async batches of 2"
grep -Eq '^share of the ceiling: synchronous [0-9]+\.[0-9]{2}, async batches of 2 [0-9]+\.[0-9]{2}$' \
  "$out" || fail "no share of the ceiling in: $(cat "$out")"
[[ "$(tail -2 "$out" | cut -d: -f1 | tr '\n' ' ')" == "env_steps_per_s_1thread env_steps_per_s_batched " ]] ||
  fail "the headline lines do not end the output: $(tail -2 "$out")"
echo "bench_env: every case measured"

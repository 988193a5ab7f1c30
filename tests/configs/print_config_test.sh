#!/usr/bin/env bash
# configs/<file>.yaml is, byte for byte, what its program prints with --print-config (the defaults
# of its options structs), so the files cannot drift from the code; programs without configuration
# keys print the header line only. With --update, rewrites the files instead of comparing.
#
#   print_config_test.sh BIN_DIR CONFIGS_DIR [--update]
set -u
bin_dir=$1
configs_dir=$2
update=${3:-}
failures=0

# program and the configs/ file holding its defaults
with_keys=(
  "generate_dataset dataset.yaml"
  "train_vae vae.yaml"
  "train_ppo ppo.yaml"
  "evaluate evaluate.yaml"
  "simulate simulate.yaml"
)
without_keys=(bench_env bench_ppo bench_collision plot_training plot_beta_sweep)

fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

printed=$(mktemp -d)
trap 'rm -rf "$printed"' EXIT

# Writes PROGRAM's --print-config output to $printed/PROGRAM.yaml; a failing run is a failure.
print_config() {
  "$bin_dir/$1" --print-config >"$printed/$1.yaml" || fail "$1 --print-config exited with $?"
}

for pair in "${with_keys[@]}"; do
  read -r program file <<<"$pair"
  print_config "$program"
  if [[ $update == --update ]]; then
    cp "$printed/$program.yaml" "$configs_dir/$file"
  elif ! diff -u "$configs_dir/$file" "$printed/$program.yaml"; then
    fail "configs/$file differs from '$program --print-config' (rerun this script with --update)"
  fi
done

# vae_figures reads train_vae's keys: the same file but for the header naming the program.
print_config vae_figures
if ! diff -u <(tail -n +2 "$configs_dir/vae.yaml") <(tail -n +2 "$printed/vae_figures.yaml"); then
  fail "vae_figures --print-config differs from configs/vae.yaml"
fi

for program in "${without_keys[@]}"; do
  print_config "$program"
  header="# $program configuration ($program --print-config); read with --config FILE.yaml."
  if ! diff -u <(echo "$header") "$printed/$program.yaml"; then
    fail "$program --print-config should print its header only"
  fi
done

if ((failures > 0)); then
  echo "$failures failure(s)"
  exit 1
fi
echo "every --print-config matches"

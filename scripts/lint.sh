#!/usr/bin/env bash
# Style and static checks. clang-format (--dry-run -Werror) on every C++ source of the project,
# clang-tidy (.clang-tidy) on every .cpp of the libraries and their programs (src env models train
# eval; not tests/) with the compile commands of $BUILD_DIR (default build/, configured here).
# Exit status non-zero on any finding.
#
#   scripts/lint.sh              # the whole project
#   scripts/lint.sh src tests/src/config_test.cpp   # only these folders or files
#   scripts/lint.sh --format-only                   # clang-format alone (seconds; CTest runs it)
#
# clang-tidy on a LibTorch translation unit takes a minute or two (it parses <torch/torch.h>;
# GCC's precompiled header is of no use to clang), so
# `scripts/lint.sh src env train/dataset eval/study` checks the torch-free libraries in minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build}"
CODE_FOLDERS=(src env models train eval tests python)
TIDY_FOLDERS='^(src|env|models|train|eval)/'

format_only=0
if [ "${1:-}" = "--format-only" ]; then
  format_only=1
  shift
fi
tools=(clang-format)
[ $format_only -eq 0 ] && tools+=(clang-tidy)
for tool in "${tools[@]}"; do
  command -v "$tool" >/dev/null ||
    { echo "lint: $tool not found (apt-get install $tool)" >&2; exit 1; }
done

targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${CODE_FOLDERS[@]}")
for target in "${targets[@]}"; do
  [ -e "$target" ] || { echo "lint: $target: no such file or folder" >&2; exit 1; }
done
mapfile -t sources < <(find "${targets[@]}" -type f \( -name '*.cpp' -o -name '*.h' \) |
  sed 's#^\./##' | sort -u)
[ ${#sources[@]} -eq 0 ] && { echo "lint: no C++ sources in $*" >&2; exit 1; }

status=0
echo "lint: clang-format on ${#sources[@]} files"
clang-format --dry-run -Werror "${sources[@]}" || status=1

tidy_sources=()
if [ $format_only -eq 0 ]; then
  mapfile -t tidy_sources < <(printf '%s\n' "${sources[@]}" | grep -E "$TIDY_FOLDERS" |
    grep '\.cpp$' || true)
fi
if [ ${#tidy_sources[@]} -gt 0 ]; then
  # Reconfigure so that files added since the last build are in compile_commands.json.
  cmake -S . -B "$BUILD_DIR" >/dev/null
  # Each file gets its unit's command: a unity build compiles several files as one unit
  # (Unity/unity_N_cxx.cxx, which #includes them). The LibTorch targets include GCC's
  # precompiled header (-include .../cmake_pch.hxx next to its .gch, which clang cannot read);
  # without it clang parses the headers each file includes.
  commands_dir="$(mktemp -d)"
  trap 'rm -rf "$commands_dir"' EXIT
  /usr/bin/python3 - "$BUILD_DIR" "$commands_dir" <<'EOF'
import json, re, sys
entries = []
for entry in json.load(open(sys.argv[1] + "/compile_commands.json")):
    command = re.sub(r" -Winvalid-pch -include \S*/cmake_pch\.hxx", "", entry["command"])
    unit = entry["file"]
    files = [unit]
    if "/Unity/" in unit:
        files = re.findall(r'^#include "(.*)"$', open(unit).read(), re.M)
    entries += [dict(entry, file=f, command=command.replace(unit, f)) for f in files]
json.dump(entries, open(sys.argv[2] + "/compile_commands.json", "w"), indent=1)
EOF
  echo "lint: clang-tidy on ${#tidy_sources[@]} files"
  printf '%s\n' "${tidy_sources[@]}" |
    xargs -P "$(nproc)" -n 1 clang-tidy -p "$commands_dir" --quiet \
      2> >(grep -v ' warnings\? generated' >&2) || status=1
fi
[ $status -eq 0 ] && echo "lint: clean"
exit $status

#!/usr/bin/env bash
# Style and static checks. clang-format (--dry-run -Werror) on every C++ source of the project,
# clang-tidy (.clang-tidy) on the .cpp files of src/ and env/ with the compile commands of
# $BUILD_DIR (default build/, configured here). Exit status non-zero on any finding.
#
#   scripts/lint.sh              # the whole project
#   scripts/lint.sh src tests/src/config_test.cpp   # only these folders or files
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build}"
TIDY_FOLDERS='^(src|env)/'

for tool in clang-format clang-tidy; do
  command -v "$tool" >/dev/null ||
    { echo "lint: $tool not found (apt-get install $tool)" >&2; exit 1; }
done

targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(src env models train eval tests benchmarks)
existing=()
for target in "${targets[@]}"; do [ -e "$target" ] && existing+=("$target"); done
[ ${#existing[@]} -eq 0 ] && { echo "lint: nothing to check" >&2; exit 1; }
mapfile -t sources < <(find "${existing[@]}" -type f \( -name '*.cpp' -o -name '*.h' \) |
  sed 's#^\./##' | sort)

status=0
echo "lint: clang-format on ${#sources[@]} files"
clang-format --dry-run -Werror "${sources[@]}" || status=1

mapfile -t tidy_sources < <(printf '%s\n' "${sources[@]}" | grep -E "$TIDY_FOLDERS" |
  grep '\.cpp$' || true)
if [ ${#tidy_sources[@]} -gt 0 ]; then
  # Reconfigure so that files added since the last build are in compile_commands.json.
  cmake -S . -B "$BUILD_DIR" >/dev/null
  echo "lint: clang-tidy on ${#tidy_sources[@]} files"
  printf '%s\n' "${tidy_sources[@]}" |
    xargs -P "$(nproc)" -n 1 clang-tidy -p "$BUILD_DIR" --quiet \
      2> >(grep -v ' warnings\? generated' >&2) || status=1
fi
[ $status -eq 0 ] && echo "lint: clean"
exit $status

#!/usr/bin/env bash
# Configures and builds the project (Release with debug info) into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
# Ninja compiles a target's units while the libraries it links are still building (Make waits);
# a folder configured before keeps its generator.
generator=()
[[ -f build/CMakeCache.txt ]] || generator=(-G Ninja)
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j "$(nproc)" "$@"

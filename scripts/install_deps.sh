#!/usr/bin/env bash
# Installs the Debian packages the project needs, only those that are missing (idempotent).
set -euo pipefail

PACKAGES=(
  cmake g++ make ninja-build ccache pkg-config clang-format git
  libtorch-dev libeigen3-dev libfcl-dev libhdf5-dev
  libyaml-cpp-dev nlohmann-json3-dev libspdlog-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  gnuplot-nox python3 python3-torch python3-h5py python3-numpy
  pybind11-dev python3-dev python3-pytest
  openmpi-bin slurm-wlm munge
  libcairo2-dev libgif-dev chromium
)

missing=()
for package in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install_deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install_deps: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

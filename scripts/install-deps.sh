#!/usr/bin/env bash
# Installs the Debian packages swarmagg builds and runs with, only those missing, so
# `make demo` and `make test` work on a fresh Debian 12 machine with one command.
# libhdf5-dev builds trajectories.h5; python3-h5py reads trajectories.h5 in the README's
# example.
#   scripts/install-deps.sh          what `make demo` needs (build and run)
#   scripts/install-deps.sh --test   also what only the tests need: slurm-wlm and munge, for
#                                    the test that runs the Slurm example under a real
#                                    single-node Slurm (tests/cluster/, part of `make test`)
set -euo pipefail
packages=(cmake g++ make pkg-config libbox2d-dev libeigen3-dev libyaml-cpp-dev libosmesa6-dev
  libpng-dev libgtest-dev libgmock-dev libcli11-dev nlohmann-json3-dev libboost-math-dev
  libbenchmark-dev gnuplot-nox libhdf5-dev)
test_packages=(slurm-wlm munge)
if [[ ${1:-} == --test ]]; then
  packages+=("${test_packages[@]}")
elif [[ -n ${1:-} ]]; then
  echo "usage: scripts/install-deps.sh [--test]" >&2
  exit 2
fi
optional=(ffmpeg python3-h5py)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${SWARMAGG_WITH_OPTIONAL:-1} == 1 ]]; then
  for p in "${optional[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
fi
if ((${#missing[@]} == 0)); then
  exit 0
fi
echo "swarmagg: installing missing Debian packages: ${missing[*]}" >&2
sudo=()
if [[ $(id -u) != 0 ]]; then
  command -v sudo >/dev/null || { echo "swarmagg: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
"${sudo[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"

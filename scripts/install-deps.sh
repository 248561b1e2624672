#!/usr/bin/env bash
# Installs the Debian packages swarmagg builds and runs with, only those missing, so
# `make demo` and `make test` work on a fresh Debian 12 machine with one command.
# libhdf5-dev builds trajectories.h5; python3-h5py reads trajectories.h5 in the README's
# example. The Python module (`import swarmagg`, docs/python.md) builds with pybind11-dev and
# python3-dev for Debian's /usr/bin/python3 and returns numpy arrays and pandas frames;
# python3-matplotlib draws its tutorial's plots. libglfw3-dev, libimgui-dev and libstb-dev
# build the live view (`swarmagg view`).
#   scripts/install-deps.sh          what `make demo` needs (build and run)
#   scripts/install-deps.sh --test   also what only the tests need: slurm-wlm and munge, for
#                                    the test that runs the Slurm example under a real
#                                    single-node Slurm (tests/cluster/); python3-pytest for
#                                    tests/python/; xvfb, xauth and xdotool for the view's
#                                    window tests on a virtual display (tests/view/)
set -euo pipefail
packages=(cmake g++ make pkg-config libbox2d-dev libeigen3-dev libyaml-cpp-dev libosmesa6-dev
  libpng-dev libgtest-dev libgmock-dev libcli11-dev nlohmann-json3-dev libboost-math-dev
  libbenchmark-dev gnuplot-nox libhdf5-dev
  pybind11-dev python3-dev python3-numpy python3-pandas python3-matplotlib
  libglfw3-dev libimgui-dev libstb-dev)
test_packages=(slurm-wlm munge python3-pytest xvfb xauth xdotool)
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

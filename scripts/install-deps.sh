#!/usr/bin/env bash
# Installs the Debian packages swarmagg builds and runs with, only those missing, so
# `make demo` and `make test` work on a fresh Debian 12 machine with one command.
#   scripts/install-deps.sh          what `make demo` needs: the compiler and the libraries of
#                                    the `swarmagg` binary (libglfw3-dev, libimgui-dev and
#                                    libstb-dev build the live view, `swarmagg view`;
#                                    libhdf5-dev trajectories.h5; gnuplot-nox draws the plots)
#   scripts/install-deps.sh --full   also what the rest of the build needs (`make build`,
#                                    `make install`): GoogleTest and Google Benchmark for the
#                                    tests and micro-benchmarks; pybind11-dev and python3-dev
#                                    build the Python module (`import swarmagg`,
#                                    docs/python.md), which returns numpy arrays and pandas
#                                    frames; python3-matplotlib draws its tutorial's plots;
#                                    and, unless SWARMAGG_WITH_OPTIONAL=0, ffmpeg for --video
#                                    and python3-h5py, which reads trajectories.h5 in the
#                                    README's example
#   scripts/install-deps.sh --test   also what only the tests need: slurm-wlm and munge, for
#                                    the test that runs the Slurm example under a real
#                                    single-node Slurm (tests/cluster/); python3-pytest for
#                                    tests/python/; xvfb, xauth and xdotool for the view's
#                                    window tests on a virtual display (tests/view/)
set -euo pipefail
packages=(cmake g++ make pkg-config libbox2d-dev libeigen3-dev libyaml-cpp-dev libosmesa6-dev
  libpng-dev libcli11-dev nlohmann-json3-dev libboost-math-dev gnuplot-nox libhdf5-dev
  libglfw3-dev libimgui-dev libstb-dev)
full_packages=(libgtest-dev libgmock-dev libbenchmark-dev
  pybind11-dev python3-dev python3-numpy python3-pandas python3-matplotlib)
test_packages=(slurm-wlm munge python3-pytest xvfb xauth xdotool)
optional=()
case ${1:-} in
  "") ;;
  --full | --test)
    packages+=("${full_packages[@]}")
    if [[ ${SWARMAGG_WITH_OPTIONAL:-1} == 1 ]]; then optional=(ffmpeg python3-h5py); fi
    if [[ $1 == --test ]]; then packages+=("${test_packages[@]}"); fi
    ;;
  *)
    echo "usage: scripts/install-deps.sh [--full | --test]" >&2
    exit 2
    ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
for p in "${optional[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
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

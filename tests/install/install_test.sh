#!/usr/bin/env bash
# `make install PREFIX=...` as a user would use it: installs the build into a temporary
# prefix, checks the layout the README promises, and runs the installed binary on an
# installed world and an installed sweep from another folder (the sweep's relative `base:`
# must still resolve).
# With the Python module built, also imports the installed `swarmagg` package from the
# prefix (PYTHONPATH=<prefix>/<python dir>, as docs/python.md says) and runs a world with it.
#   tests/install/install_test.sh BUILD_DIR [PYTHON PYTHON_DIR]
set -euo pipefail
build_dir=${1:?usage: install_test.sh BUILD_DIR [PYTHON PYTHON_DIR]}
python=${2:-}
python_dir=${3:-}
tmp=$(mktemp -d /tmp/swarmagg-install.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build_dir" --prefix "$tmp/prefix" >/dev/null
for f in bin/swarmagg share/doc/swarmagg/README.md share/doc/swarmagg/docs/rendering.md share/doc/swarmagg/docs/frame-full-0.0025.png \
  share/doc/swarmagg/bench/results/README.md \
  share/swarmagg/worlds/examples/demo.yaml share/swarmagg/worlds/paper/full-0.0025.yaml \
  share/swarmagg/examples/sweeps/p-leave-vs-count.yaml share/swarmagg/examples/slurm/sweep.sbatch; do
  [[ -f $tmp/prefix/$f ]] || fail "$f not installed"
done
# The installed pages' relative links resolve within the installed documentation.
/usr/bin/python3 "$(dirname "$0")/../docs/check_links.py" "$tmp/prefix/share/doc/swarmagg" >/dev/null ||
  fail "installed docs have broken links: $(/usr/bin/python3 "$(dirname "$0")/../docs/check_links.py" \
    "$tmp/prefix/share/doc/swarmagg" | head -3)"
for f in bin/swarmagg share/swarmagg/examples/slurm/submit.sh; do
  [[ -x $tmp/prefix/$f ]] || fail "$f not executable"
done

cd "$tmp"
export PATH=$tmp/prefix/bin:$PATH
# Outputs are captured before they are searched: `grep -q` stops reading at the first match,
# and under pipefail the writer's SIGPIPE would fail the check at random.
version=$(swarmagg --version)
[[ -n $version ]] || fail "swarmagg --version printed nothing"
share=$tmp/prefix/share/swarmagg
swarmagg run "$share/worlds/examples/demo.yaml" --replicates 1 --set run.duration=10 --no-model \
  --quiet --out run
[[ -f run/world.resolved.yaml ]] || fail "the installed binary wrote no run"
listed=$(swarmagg sweep "$share/examples/sweeps/p-leave-vs-count.yaml" --list)
[[ $listed == *pending* ]] || fail "the installed sweep does not load"
# From a folder with no worlds/paper, reproduce finds the installed paper worlds.
swarmagg reproduce --quick --only creation-50 --quiet --out reproduced ||
  fail "the installed reproduce does not find the installed paper worlds"
[[ -f reproduced/REPORT.md ]] || fail "the installed reproduce wrote no report"
if [[ -n $python ]]; then
  package=$tmp/prefix/$python_dir/swarmagg
  [[ -f $package/__init__.py ]] || fail "the Python package is not in $python_dir"
  ls "$package"/_core*.so >/dev/null 2>&1 || fail "the Python extension is not in $python_dir"
  PYTHONPATH=$tmp/prefix/$python_dir PYTHONNOUSERSITE=1 "$python" - "$share" "$package" <<'PY' ||
import sys
from pathlib import Path
import swarmagg as sa
share, package = sys.argv[1], Path(sys.argv[2])
assert Path(sa.__file__).parent == package, f"imported {sa.__file__}, not the installed package"
world = sa.load_world(f"{share}/worlds/examples/demo.yaml", set={"run.duration": 5})
frame = sa.run(world, replicates=1).timeseries()
assert list(frame["step"])[-1] == world.steps, frame
PY
    fail "the installed Python module does not import or run"
  echo "the installed Python module imports from the prefix and runs the installed world"
fi
echo "installed into a temporary prefix; the installed swarmagg runs the installed world and sweep"

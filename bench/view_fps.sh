#!/usr/bin/env bash
# Frame rate of `swarmagg view` under Xvfb (Mesa llvmpipe), playing 1 step per frame with the
# panel shown: the demo world, a paper world (creation-150) and 10^4 agents at the demo's
# density. Each line is the view's own report (--frames): fps and where a frame's time went.
# Usage: bench/view_fps.sh [BUILD_DIR] [FRAMES]   (needs xvfb-run: scripts/install-deps.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
frames=${2:-300}
swarmagg=$build/swarmagg
script=$(mktemp)
trap 'rm -f "$script"' EXIT
# view LABEL SCRIPT_TEXT WORLD [OPTIONS...]
view() {
  local label=$1
  printf '%b' "$2" > "$script"
  shift 2
  printf '%-44s ' "$label"
  xvfb-run -a -s '-screen 0 1280x1024x24' "$swarmagg" view "$@" --script "$script" \
    --frames "$frames" | grep '^view:'
}
view "demo (60 agents, 800x800)" 'play\n' "$root/worlds/examples/demo.yaml"
view "creation-150 (paper, 150 agents, 800x800)" 'play\n' "$root/worlds/paper/creation-150.yaml"
view "soysal-5-constant (paper, 5 agents, 800x800)" 'play\n' "$root/worlds/paper/soysal-5-constant.yaml"
# 10^4 agents on 1549 x 1549: the demo's density (60 on 120 x 120).
big=(--set robots.count=10000 --set arena.width=1549 --set arena.height=1549)
view "10^4 agents, 800x800" 'play\n' "$root/worlds/examples/demo.yaml" "${big[@]}"
view "10^4 agents, detection circles off" 'overlay detection off\nplay\n' \
  "$root/worlds/examples/demo.yaml" "${big[@]}"

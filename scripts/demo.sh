#!/usr/bin/env bash
# `make demo`: runs the example world, renders its first replicate and says where it all is.
set -euo pipefail
swarmagg=${1:-build/swarmagg}
world=worlds/examples/demo.yaml
out=runs/demo
# --force: the demo writes the same folders each time it is run.
"$swarmagg" run "$world" --out "$out" --render-every 20 --render-dir renders/demo --force
echo
echo "demo outputs:"
echo "  $out/timeseries.csv   NOA, state counts and events over time, per replicate"
echo "  $out/summary.json     final values per replicate and their spread"
echo "  $out/world.resolved.yaml  every parameter that ran, with the seeds"
for png in noa states sizes; do
  if [ -f "$out/$png.png" ]; then echo "  $out/$png.png  drawn by $out/plots/$png.gp from the CSVs beside it"; fi
done
echo "  renders/demo/frame_*.png  $(ls renders/demo/frame_*.png 2>/dev/null | wc -l) frames of replicate 0"

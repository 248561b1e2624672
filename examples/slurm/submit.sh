#!/usr/bin/env bash
# Submits a sweep to Slurm: a job array of SHARDS tasks (sweep.sbatch, one shard each) and a
# merge job that starts once every task has succeeded. Works from any folder; swarmagg must
# be on PATH (`make install PREFIX=...`), on the nodes too.
#
#   examples/slurm/submit.sh SWEEP.yaml [SHARDS] [SBATCH_OPTION ...]
#
# Results go to $RESULTS (default results/<sweep file name without .yaml>): shard-<i>/ per
# task, logs/, and the merged sweep_timeseries.csv, sweep_summary.csv and sweep.json. Options after SHARDS go to
# both sbatch calls and override the #SBATCH lines (e.g. --cpus-per-task=4 --partition=short).
# Running it again with the same SHARDS resumes: completed runs are skipped. If a task fails
# or is cancelled, the merge is cancelled too (nothing waits forever); submit again.
# Prints the array's and the merge's job ids.
set -euo pipefail

usage="usage: $0 SWEEP.yaml [SHARDS] [SBATCH_OPTION ...]"
sweep=${1:?$usage}
shards=${2:-8}
shift $(($# < 2 ? $# : 2))
[[ -f $sweep ]] || { echo "$0: no sweep file $sweep" >&2; exit 2; }
[[ $shards =~ ^[1-9][0-9]*$ ]] || { echo "$0: SHARDS must be a positive integer, got '$shards'" >&2; exit 2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
results=${RESULTS:-results/$(basename "$sweep" .yaml)}

# Slurm opens --output before a job starts, so the log folder must exist at submission.
mkdir -p "$results/logs"
array=$(sbatch --parsable --array="1-$shards" --output="$results/logs/%x-%A_%a.out" "$@" \
  "$here/sweep.sbatch" "$sweep" "$results" "$shards")
array=${array%%;*}  # --parsable prints "id" or "id;cluster"
merge=$(sbatch --parsable --job-name=swarmagg-merge --dependency="afterok:$array" \
  --kill-on-invalid-dep=yes --output="$results/logs/%x-%j.out" "$@" \
  --wrap "swarmagg merge $(printf '%q' "$results")/shard-* --out $(printf '%q' "$results")")
merge=${merge%%;*}
echo "array $array ($shards shards) -> $results/shard-*"
echo "merge $merge (after the array succeeds) -> $results"

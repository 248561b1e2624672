#!/usr/bin/env bash
# The Slurm path under real Slurm: starts a single-node cluster on localhost (munged,
# slurmctld, slurmd, all in a temporary folder with their own socket and ports, so a system
# Slurm is left alone), installs swarmagg into a temporary prefix, and from a fresh folder
#   1. submits a sweep with examples/slurm/submit.sh (3 shards + dependent merge) and checks
#      the merged outputs are byte-identical to an unsharded `swarmagg sweep`;
#   2. submits it again into a new folder, scancels one shard mid-run (some of its runs
#      complete, some not), checks the merge was cancelled with it, resubmits, and checks the
#      resumed sweep merges to the same bytes.
# Every daemon it started is stopped by pid on exit (trap), whatever happened. Every wait is
# bounded. Needs root (munged runs as the munge user, slurmd as root).
#   tests/cluster/slurm_sweep_test.sh [BUILD_DIR]      (make test-slurm)
# Exit 0 pass, 1 fail, 77 skipped (not root, or Slurm/munge not installed).
set -euo pipefail

source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build_dir=$(cd "${1:-$source_dir/build}" && pwd)
sweep_file=$source_dir/tests/data/cluster/slurm-sweep.yaml
shards=3
wait_limit=${SLURM_TEST_WAIT:-240}  # seconds any one wait may take

t0=${EPOCHREALTIME/./}
say() { printf '[slurm-test %6.1fs] %s\n' "$(((${EPOCHREALTIME/./} - t0) / 100000))e-1" "$*"; }
fail() { say "FAIL: $*"; exit 1; }

if [[ $(id -u) != 0 ]]; then echo "skipped: needs root (munged, slurmd)"; exit 77; fi
for tool in munged slurmctld slurmd sbatch squeue scancel setpriv; do
  command -v "$tool" >/dev/null || { echo "skipped: $tool not installed (scripts/install-deps.sh --test)"; exit 77; }
done
id munge >/dev/null 2>&1 || { echo "skipped: no munge user (package munge)"; exit 77; }

tmp=$(mktemp -d /tmp/swarmagg-slurm.XXXXXX)
chmod 755 "$tmp"  # munged runs as the munge user and must reach its folder
pids=()

stop_daemons() {
  local status=$?
  set +e
  if [[ -n ${SLURM_CONF:-} && -S $tmp/munge/socket ]]; then
    # Jobs first, while slurmd can still kill them; then the daemons, newest first.
    scancel --quiet --user=root 2>/dev/null
    for _ in $(seq 50); do [[ -z $(squeue -h -o %i 2>/dev/null) ]] && break; sleep 0.2; done
  fi
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do kill -TERM "${pids[i]}" 2>/dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
    kill -0 "$pid" 2>/dev/null && { echo "daemon $pid ignored SIGTERM: SIGKILL"; kill -KILL "$pid"; }
    wait "$pid" 2>/dev/null
  done
  if ((status != 0)); then
    for log in "$tmp"/log/*.log; do echo "--- $log (tail)"; tail -n 15 "$log"; done
  fi
  rm -rf "$tmp"
  exit "$status"
}
trap stop_daemons EXIT
trap 'exit 130' INT TERM

# Waits until `$@` succeeds, at most wait_limit seconds.
wait_until() {
  local what=$1 deadline=$((SECONDS + wait_limit))
  shift
  until "$@"; do
    ((SECONDS < deadline)) || fail "timed out after ${wait_limit}s waiting for $what"
    for pid in "${pids[@]}"; do kill -0 "$pid" 2>/dev/null || fail "daemon $pid died (logs below)"; done
    sleep 0.5
  done
}
# A squeue that fails (a slurmctld timeout prints nothing on stdout) is not an empty queue.
queue_empty() {
  local ids
  ids=$(squeue -h -o %i) || return 1
  [[ -z $ids ]]
}

# --- swarmagg, installed as a user would --------------------------------------------------
cmake --install "$build_dir" --prefix "$tmp/prefix" >/dev/null
export PATH=$tmp/prefix/bin:$PATH
[[ $(command -v swarmagg) == "$tmp/prefix/bin/swarmagg" ]] || fail "installed swarmagg not on PATH"
submit=$tmp/prefix/share/swarmagg/examples/slurm/submit.sh
[[ -x $submit ]] || fail "submit.sh not installed executable"

# --- munge --------------------------------------------------------------------------------
mkdir -p "$tmp/munge" "$tmp/log" "$tmp/state" "$tmp/spool"
dd if=/dev/urandom of="$tmp/munge/key" bs=1024 count=1 status=none
chown -R munge:munge "$tmp/munge"
chmod 700 "$tmp/munge"
chmod 400 "$tmp/munge/key"
touch "$tmp/log/munged.log" && chown munge "$tmp/log/munged.log"
setpriv --reuid=munge --regid=munge --init-groups munged --foreground --force \
  --socket="$tmp/munge/socket" --key-file="$tmp/munge/key" --pid-file="$tmp/munge/pid" \
  --seed-file="$tmp/munge/seed" --log-file="$tmp/log/munged.log" >/dev/null 2>&1 &
pids+=($!)
wait_until "munged's socket" test -S "$tmp/munge/socket"

# --- slurm.conf: one node, this host at 127.0.0.1 (no name lookup), free ports ------------
# A port nothing listens on (nothing answers a connection), picked at random.
free_port() {
  local port
  while :; do
    port=$((20000 + RANDOM % 40000))
    (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null || { echo "$port"; return; }
  done
}
host=$(hostname -s)
cat >"$tmp/slurm.conf" <<CONF
ClusterName=swarmaggtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$tmp/munge/socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
KillWait=5
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" >/dev/null 2>&1 &
pids+=($!)
slurmd -D -N "$host" -f "$SLURM_CONF" >/dev/null 2>&1 &
pids+=($!)
node_idle() { [[ $(sinfo -h -N -o %t 2>/dev/null) == idle ]]; }
wait_until "the node to be idle" node_idle
say "single-node Slurm up: munged ${pids[0]}, slurmctld ${pids[1]}, slurmd ${pids[2]}, $(nproc) CPUs"

# --- the unsharded reference (while nothing else runs) -----------------------------------
swarmagg sweep "$sweep_file" --out "$tmp/reference" --threads 2 --quiet
runs=$(swarmagg sweep "$sweep_file" --list | grep -c ' pending')
say "reference: unsharded sweep of $runs runs done"

same_as_reference() {
  local dir=$1
  for f in sweep_timeseries.csv sweep_summary.csv sweep.json; do
    [[ -f $dir/$f ]] || fail "$dir/$f missing"
    cmp "$tmp/reference/$f" "$dir/$f" || fail "$dir/$f differs from the unsharded sweep"
  done
}
# Complete runs of shard $2 of a results folder $1.
complete_runs() { swarmagg sweep "$sweep_file" --shard "$2/$shards" --out "$1/shard-$2" --list | grep -c ' complete' || true; }
shard_runs() { swarmagg sweep "$sweep_file" --shard "$1/$shards" --list | grep -c ' pending' || true; }

# --- 1. submit from a fresh folder, wait, compare ----------------------------------------
mkdir "$tmp/fresh" && cd "$tmp/fresh"
RESULTS=results "$submit" "$sweep_file" "$shards" --cpus-per-task=1 | sed 's/^/  submit.sh: /'
wait_until "the array and the merge to finish" queue_empty
for i in $(seq "$shards"); do say "shard $i/$shards: $(complete_runs results "$i") of $(shard_runs "$i") runs complete"; done
same_as_reference results
say "merge: sweep_timeseries.csv, sweep_summary.csv, sweep.json byte-identical to the unsharded sweep"

# --- 2. cancel one shard mid-run, resubmit, compare --------------------------------------
mkdir "$tmp/resume" && cd "$tmp/resume"
out=$(RESULTS=results "$submit" "$sweep_file" "$shards" --cpus-per-task=1)
array=$(sed -n 's/^array \([0-9]*\).*/\1/p' <<<"$out")
merge=$(sed -n 's/^merge \([0-9]*\).*/\1/p' <<<"$out")
victim=2
some_done() { (($(complete_runs results $victim) >= 1)); }
wait_until "shard $victim's first complete run" some_done
scancel "${array}_$victim"
task_gone() { [[ -z $(squeue -h -j "${array}_$victim" -o %i 2>/dev/null) ]]; }
wait_until "the cancelled task to end" task_gone
done_before=$(complete_runs results $victim)
total=$(shard_runs $victim)
say "scancel ${array}_$victim: shard $victim stopped with $done_before of $total runs complete"
sed 's/^/  cancelled task log: /' "results/logs/swarmagg-sweep-${array}_$victim.out"
((done_before < total)) || fail "shard $victim finished before the scancel: make its runs longer"
# The complete runs' resolved worlds, with their modification times: a resumed shard must
# skip these runs, not redo them.
kept=$(find "results/shard-$victim" -name world.resolved.yaml -exec stat -c '%n %y' {} + | sort)
wait_until "the rest of the array (the merge is cancelled with the failed task)" queue_empty
[[ ! -f results/sweep_summary.csv ]] || fail "the merge ran although a shard was cancelled"
# Redo only the cancelled task by hand: an array of that one task, given the number of shards
# (its upper bound alone would make it shard $victim/$victim).
sbatch --parsable --array="$victim" --cpus-per-task=1 --output="results/logs/%x-%A_%a.out" \
  "$(dirname "$submit")/sweep.sbatch" "$sweep_file" results "$shards" >/dev/null
wait_until "the redone task" queue_empty
redone=$(complete_runs results $victim)
held=$(find "results/shard-$victim" -name world.resolved.yaml | wc -l)
((redone == total && held == total)) ||
  fail "the redone task left shard-$victim with $redone of its $total runs complete and $held runs in all"
say "redo of task $victim alone: shard $victim/$shards complete, no other shard's runs"
RESULTS=results "$submit" "$sweep_file" "$shards" --cpus-per-task=1 | sed 's/^/  resubmit: /'
wait_until "the resubmitted array and merge" queue_empty
sed 's/^/  merge log: /' results/logs/swarmagg-merge-*.out
say "resume: shard $victim now $(complete_runs results $victim) of $total runs complete"
now=$(find "results/shard-$victim" -name world.resolved.yaml -exec stat -c '%n %y' {} + | sort)
[[ $(comm -23 <(echo "$kept") <(echo "$now")) == "" ]] || fail "the resumed shard redid complete runs"
say "resume: the $done_before runs complete before the scancel were kept, not run again"
same_as_reference results
say "resumed merge byte-identical to the unsharded sweep"
say "PASS (the daemons stop on exit)"

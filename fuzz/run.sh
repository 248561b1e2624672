#!/usr/bin/env bash
# `make fuzz`: builds the libFuzzer targets with clang++, ASan and UBSan in build-fuzz/ and
# runs each for FUZZ_SECONDS (default 60). Seeds: the worlds in worlds/ and tests/data/ (good
# and bad) for the world file, fuzz/seeds/override/ for --set. New inputs accumulate in
# build-fuzz/corpus/, so later runs start where earlier ones stopped. A crash, a hang (a unit
# slower than 10 s) or a leak stops the run with the input in build-fuzz/artifacts/: make it
# a regression file in tests/data/bad/ (or a good world) and fix the loader.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${FUZZ_BUILD_DIR:-build-fuzz}
seconds=${FUZZ_SECONDS:-60}
jobs=${JOBS:-$(nproc)}

if ! command -v clang++ >/dev/null || ! compgen -G "/usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a" >/dev/null; then
  echo "fuzz: needs clang++ and libFuzzer (Debian: apt-get install clang libclang-rt-14-dev)" >&2
  exit 1
fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DSWARMAGG_FUZZ=ON -DSWARMAGG_SANITIZE=ON -DBUILD_TESTING=OFF >/dev/null
cmake --build "$build" --target fuzz_world_loader fuzz_override -j "$jobs"
mkdir -p "$build/corpus/world_loader" "$build/corpus/override" "$build/artifacts"

# Runs one target; the full libFuzzer log stays in build-fuzz/fuzz_<name>.log.
run() {
  local name=$1
  shift
  local log="$build/fuzz_$name.log"
  echo "fuzz_$name: ${seconds}s (log: $log)"
  if ! "$build/fuzz/fuzz_$name" "$build/corpus/$name" "$@" -dict=fuzz/world.dict -max_len=8192 \
    -timeout=10 -rss_limit_mb=2048 -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix="$build/artifacts/$name-" >"$log" 2>&1; then
    tail -n 60 "$log"
    echo "fuzz_$name FAILED: the input is in $build/artifacts/" >&2
    return 1
  fi
  grep -E '^(Done [0-9]+ runs|stat::number_of_executed_units|stat::new_units_added)' "$log"
}

run world_loader worlds tests/data
run override fuzz/seeds/override

# Two commands do all set-up on a fresh Debian 12 machine: `make demo` and `make test`.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
SWARMAGG := $(BUILD_DIR)/swarmagg

.PHONY: deps deps-full deps-test configure build install demo test test-slurm bench microbench clean fuzz test-sanitize

# What the demo needs: the compiler and the libraries of the swarmagg binary.
deps:
	@scripts/install-deps.sh

# Also what the rest of the build needs (GoogleTest, Google Benchmark, the Python module).
deps-full:
	@scripts/install-deps.sh --full

# Also what only the tests need (Slurm and munge for tests/cluster/, pytest, xvfb).
deps-test:
	@scripts/install-deps.sh --test

# The whole build: a build folder that `make demo` configured without the tests and the
# Python module gets them back here.
configure: deps-full
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DSWARMAGG_PYTHON=ON >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# bin/swarmagg, share/doc/swarmagg (README, docs), share/swarmagg (worlds, examples) and the
# Python package in lib/python3.X/dist-packages/swarmagg (docs/python.md).
PREFIX ?= /usr/local
install: build
	@cmake --install $(BUILD_DIR) --prefix $(PREFIX)

# Only the swarmagg binary: a new build folder is configured without the tests and the Python
# module, whose packages the demo does not install; an existing one keeps its settings.
demo: deps
	@test -f $(BUILD_DIR)/CMakeCache.txt || cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release \
	  -DBUILD_TESTING=OFF -DSWARMAGG_PYTHON=OFF >/dev/null
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target swarmagg
	@scripts/demo.sh $(SWARMAGG)

test: deps-test build
	@ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

# A single-node Slurm on localhost runs the example sweep through examples/slurm/submit.sh
# (tests/cluster/slurm_sweep_test.sh; needs root for munged and slurmd).
test-slurm: deps-test build
	@tests/cluster/slurm_sweep_test.sh $(BUILD_DIR)

# The whole suite built with AddressSanitizer and UndefinedBehaviorSanitizer (Debug, so
# every replicate also checks its invariants, at -O1 to keep it fast enough).
SANITIZE_DIR ?= build-sanitize
test-sanitize: deps-test
	@cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
	  -DSWARMAGG_SANITIZE=ON >/dev/null
	@cmake --build $(SANITIZE_DIR) -j $(JOBS)
	@LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	  ctest --test-dir $(SANITIZE_DIR) --output-on-failure -j $(JOBS)

# libFuzzer on the world loader and on --set (clang++, ASan + UBSan), FUZZ_SECONDS per target.
FUZZ_SECONDS ?= 60
fuzz: deps-full
	@FUZZ_SECONDS=$(FUZZ_SECONDS) JOBS=$(JOBS) fuzz/run.sh

bench: build
	@$(SWARMAGG) bench

# Google Benchmark micro-benchmarks of the kinematic hot path (bench/), one per stage.
MICROBENCHES := neighbours encounters aggregates controller
microbench: build
	@for b in $(MICROBENCHES); do $(BUILD_DIR)/bench/bench_$$b || exit 1; done

clean:
	@rm -rf $(BUILD_DIR)

# crowdsim-bench entry points. `make run` and `make test` do everything on a fresh Debian 12
# machine: install what is missing (scripts/install_deps.sh), configure, build, run.
BUILD ?= build
JOBS ?= $(shell nproc)
SUITE ?= suites/quick.yaml
CMAKE_FLAGS ?=

.PHONY: all deps configure build run test bench train-all gallery python package clean

all: build

# A build without libtorch (CMAKE_FLAGS=-DCROWDSIM_WITH_TORCH=OFF) does not install it either.
deps:
	@scripts/install_deps.sh $(if $(findstring CROWDSIM_WITH_TORCH=OFF,$(CMAKE_FLAGS)),--no-torch)

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j$(JOBS)

# Runs the default suite and prints its table (results in runs/<suite name>/; the committed
# reference outputs under results/ are written only with an explicit --out).
run: build
	$(BUILD)/bin/crowdsim-bench run $(SUITE)

# Builds and runs every unit and integration test (ctest prints its summary).
test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS) --timeout 900

# Runs every Google Benchmark (one core each, one after another); stops at one that fails.
# build/bench/ also holds rvo2_overlap_stats, a helper of tests/bench/orca/overlap_stats.sh.
bench: build
	@for b in $(BUILD)/bench/*_bench; do echo "== $$b"; $$b --benchmark_min_time=0.2 || exit 1; done
	@if [ -d $(BUILD)/python/crowdsim_bench ]; then echo "== tests/bench/python/env_bench.py"; \
	  PYTHONPATH=$(BUILD)/python /usr/bin/python3 tests/bench/python/env_bench.py; fi

# Trains every file under suites/train/ that has no finished training yet, TRAIN_JOBS at a time
# (nice'd, one core each), resuming interrupted ones: hours of work, see docs/training.md.
TRAIN_JOBS ?= 2
train-all: build
	scripts/train_all.sh -j $(TRAIN_JOBS) --build $(BUILD)

# Builds the Python package crowdsim_bench into $(BUILD)/python (part of `make build` too).
python: build
	@echo "crowdsim_bench is in $(BUILD)/python: PYTHONPATH=$(BUILD)/python python3 -c 'import crowdsim_bench'"

# A Debian package of the install (CLI, core library and SDK headers, plugins, Python package,
# worlds, suites, models) under /usr: $(BUILD)/crowdsim-bench_VERSION_ARCH.deb.
package: build
	cd $(BUILD) && cpack -G DEB

# Redraws docs/gallery/*.png and the README's docs/episode.png from the committed results.
gallery: build
	scripts/make_gallery.sh --bin $(BUILD)/bin/crowdsim-bench

clean:
	rm -rf $(BUILD)

# Photopic: every entry point installs missing Debian packages first (scripts/deps.sh), then configures with
# CMakePresets.json and builds. The release CLI is build/release/photopic.
JOBS ?= $(shell nproc)
CTEST_FLAGS ?= --output-on-failure -j$(JOBS)

.PHONY: all deps build demo test bench install clean format

all: build

deps:
	@scripts/deps.sh

build: deps
	@cmake --preset release > build-configure.log 2>&1 || (cat build-configure.log; exit 1)
	cmake --build --preset release -j$(JOBS)

demo: build
	build/release/photopic demo -o out/demo

test: build
	@scripts/check-standalone.sh
	cd build/release && ctest $(CTEST_FLAGS)
	@echo "== core tests under AddressSanitizer + UndefinedBehaviorSanitizer"
	@cmake --preset asan > build-configure-asan.log 2>&1 || (cat build-configure-asan.log; exit 1)
	cmake --build --preset asan -j$(JOBS)
	cd build/asan && ctest $(CTEST_FLAGS)
	@echo "== library use: install, then build examples/minimal against the installed package"
	cmake --install build/release --prefix build/install > /dev/null
	cmake -S examples/minimal -B build/example -DCMAKE_PREFIX_PATH=$(CURDIR)/build/install > build-configure-example.log 2>&1 || (cat build-configure-example.log; exit 1)
	cmake --build build/example -j$(JOBS)
	build/example/photopic_minimal

# On Mesa llvmpipe a 1080p frame takes ~0.15 s, so the whole target runs in about a minute there; read the timer
# query columns on a GPU and the --sync / wall+finish columns on llvmpipe (apps/cli/Bench.cpp explains why).
BENCH_FRAMES ?= 60
bench: build
	@if [ -x build/release/bench/photopic_bench ]; then build/release/bench/photopic_bench; else echo "no benchmarks yet"; fi
	build/release/photopic bench --size 1920x1080 --frames $(BENCH_FRAMES)
	build/release/photopic bench --scene canvas --size 1920x1080 --frames $(BENCH_FRAMES)

install: build
	cmake --install build/release

format:
	find src apps tests bench examples -name '*.h' -o -name '*.cpp' | xargs clang-format -i

clean:
	rm -rf build out build-configure*.log

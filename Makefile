# Photopic: every entry point installs missing Debian packages first (scripts/deps.sh), then configures with
# CMakePresets.json and builds. The release CLI is build/release/photopic.
JOBS ?= $(shell nproc)
CTEST_FLAGS ?= --output-on-failure -j$(JOBS)

.PHONY: all deps build demo test docs settings-doc bench fuzz soak asan-all tsan install clean format

all: build

deps:
	@scripts/deps.sh

build: deps
	@cmake --preset release > build-configure.log 2>&1 || (cat build-configure.log; exit 1)
	cmake --build --preset release -j$(JOBS)

demo: build
	build/release/photopic demo -o out/demo
	build/release/photopic demo --scene orbit -o out/demo-orbit

test: build
	@scripts/check-standalone.sh
	@scripts/check-paths.py
	cd build/release && ctest $(CTEST_FLAGS)
	@echo "== core tests under AddressSanitizer + UndefinedBehaviorSanitizer"
	@cmake --preset asan > build-configure-asan.log 2>&1 || (cat build-configure-asan.log; exit 1)
	cmake --build --preset asan -j$(JOBS)
	cd build/asan && ctest $(CTEST_FLAGS)
	@echo "== library use: install, then build and run examples/minimal and examples/glfw-host against it"
	JOBS=$(JOBS) scripts/check-library.sh
	@echo "== API reference (warnings are errors: every public declaration is documented)"
	@$(MAKE) --no-print-directory docs

# docs/settings.md, the reference of every setting, from the settings reflection (the e2e test
# settings_reference fails while the committed file differs from this output).
settings-doc: build
	build/release/photopic settings --markdown > docs/settings.md

# The API reference of include/photopic/ into build/docs/html (Doxygen from Debian).
docs: deps
	@mkdir -p build/docs
	doxygen docs/Doxyfile
	@echo "API reference: build/docs/html/index.html"

# The per-pass tables at 720p, 1080p, 4K and 8K, each beside the same run's copy reference, and the scaling
# summary, into out/bench/ (scripts/bench-table.sh). On Mesa llvmpipe a 1080p frame takes ~0.15 s, so the
# target takes a few minutes there; read the timer query columns on a GPU (apps/cli/Bench.cpp explains why).
BENCH_FRAMES ?= 20
bench: build
	@if [ -x build/release/bench/photopic_bench ]; then build/release/bench/photopic_bench; else echo "no benchmarks yet"; fi
	scripts/bench-table.sh build/release/photopic $(BENCH_FRAMES)
	build/release/photopic bench --scene canvas --size 1920x1080 --frames $(BENCH_FRAMES) --json out/bench/canvas.json

# Fuzzing (fuzz/): libFuzzer + ASan/UBSan harnesses built by clang in their own tree, each run for FUZZ_SECONDS
# on one core, FUZZ_PARALLEL at a time. The committed corpus also runs in `make test`
# (photopic_fuzz_corpus_tests), with any compiler.
FUZZ_SECONDS ?= 60
FUZZ_PARALLEL ?= 1
FUZZ_TARGETS ?= settings override motion camera exr exrframe hdr png gltf
fuzz: deps
	@CC=clang CXX=clang++ cmake -S . -B build/fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPHOTOPIC_BUILD_FUZZERS=ON \
		-DPHOTOPIC_BUILD_TESTS=OFF -DPHOTOPIC_BUILD_APPS=OFF -DPHOTOPIC_BUILD_BENCH=OFF > build-configure-fuzz.log 2>&1 \
		|| (cat build-configure-fuzz.log; exit 1)
	cmake --build build/fuzz -j$(JOBS) --target $(addprefix photopic_fuzz_,$(FUZZ_TARGETS))
	FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_PARALLEL=$(FUZZ_PARALLEL) fuzz/run.sh build/fuzz $(FUZZ_TARGETS)

# Memory over a long run: 100,000 tabletop frames at 64x36 (every 1000th written), resident memory printed
# after the first and the last frame; fails when it grew by more than SOAK_MAX_GROWTH_KB.
SOAK_FRAMES ?= 100000
SOAK_MAX_GROWTH_KB ?= 5120
soak: build
	scripts/soak.sh build/release/photopic $(SOAK_FRAMES) $(SOAK_MAX_GROWTH_KB)

# Every target (GL host code, scenes, CLI, viewer) and its tests under ASan + UBSan in build/asan-all; about an
# hour on two cores, so not part of `make test`, which runs the core under them (docs/reliability.md).
asan-all: deps
	JOBS=$(JOBS) scripts/asan-all.sh build/asan-all

# The CLI's threads (sequence streaming, the scenes' writers) under ThreadSanitizer in build/tsan; about 6
# minutes on two cores, run by hand (docs/reliability.md).
tsan: deps
	JOBS=$(JOBS) scripts/tsan.sh build/tsan

install: build
	cmake --install build/release

format:
	find src apps tests bench examples -name '*.h' -o -name '*.cpp' | xargs clang-format -i

clean:
	rm -rf build out build-configure*.log

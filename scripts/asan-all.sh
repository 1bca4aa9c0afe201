#!/usr/bin/env bash
# Every target (GL host code, passes, scenes, CLI, viewer and their tests) under AddressSanitizer and
# UndefinedBehaviorSanitizer, in a build tree of its own, then its tests. `make test` covers only the GL-free
# core this way (the `asan` preset); this takes about an hour on two cores, so it is run by hand.
# Usage: scripts/asan-all.sh [BUILD_DIR]   (`make asan-all`; JOBS sets the parallelism)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/asan-all}"
jobs="${JOBS:-$(nproc)}"
# RelWithDebInfo: -O2 -g, asserts off (as in the release build the tests otherwise run).
flags="-fsanitize=address,undefined -fno-omit-frame-pointer"
mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPHOTOPIC_BUILD_BENCH=OFF \
    -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" > "$build/configure.log" 2>&1 \
    || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j"$jobs"

# The GL driver is unloaded at exit (dlclose), after which LeakSanitizer no longer sees the pointers its data
# held and reports the driver's objects as leaks from no known module. A dlclose that does nothing keeps it
# mapped, so that what is left is what the project leaks.
keep="$(cd "$build" && pwd)/keep-loaded.so"
scripts/keep-loaded.sh "$keep"
libasan="$(cc -print-file-name=libasan.so)"

echo "== the test suites (leaks checked)"
(cd "$build" && LD_PRELOAD="$libasan:$keep" ASAN_OPTIONS=detect_leaks=1 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest -j"$jobs" -E '^e2e\.' --output-on-failure)
# e2e runs bash and python too (not instrumented): no leak checks there. A sanitizer report exits 99, which
# no script expects, so it cannot pass for an expected failure. standalone and install build the project
# again, without the sanitizers.
echo "== the e2e scripts but standalone and install"
(cd "$build" && ASAN_OPTIONS=detect_leaks=0:exitcode=99 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:exitcode=99 \
    ctest -j"$jobs" -R '^e2e\.' -E '^e2e\.(standalone|install)$' --output-on-failure)

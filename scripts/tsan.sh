#!/usr/bin/env bash
# The CLI's threads under ThreadSanitizer: `photopic` and every library of the project built with
# -fsanitize=thread in a build tree of its own, then the runs that use its threads (a sequence streamed with
# 2 to 4 frames in flight, 2D and 3D with TAA, every output format, a run stopped by a bad frame, the scenes'
# streaming writers). A ThreadSanitizer report ends the run it comes from with exit 66, which none expects.
# OpenEXR's decode pool is left out (--decode-threads 0): it hands its results back through synchronisation
# inside the uninstrumented OpenEXR library, which TSan cannot see, and reports races that are not there.
# About 6 minutes on two cores; run by hand.
# Usage: scripts/tsan.sh [BUILD_DIR]   (`make tsan`; JOBS sets the parallelism)
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$(pwd)"
build="${1:-build/tsan}"
jobs="${JOBS:-$(nproc)}"
mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPHOTOPIC_BUILD_TESTS=OFF \
    -DPHOTOPIC_BUILD_BENCH=OFF -DPHOTOPIC_BUILD_FUZZERS=OFF -DCMAKE_C_FLAGS="-fsanitize=thread" \
    -DCMAKE_CXX_FLAGS="-fsanitize=thread -O1 -g" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" \
    > "$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j"$jobs" --target photopic

photopic="$(cd "$build" && pwd)/photopic"
work="$(cd "$build" && pwd)/runs"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
# The GL driver (llvmpipe here) is not instrumented: TSan sees none of its plain loads and stores, and of its
# synchronisation only the pthread calls, not the futexes Mesa's own locks and queues are made of, so it
# reports races between the driver's threads on the driver's data (a lock its worker held, freed by the GL
# thread after a mipmap build). The calls it makes into TSan's interceptors are left out like the rest of it.
# TSan stops a process that unloads a library so named: a dlclose that does nothing keeps the driver mapped.
echo "called_from_lib:swrast_dri.so" > suppressions.txt
"$repo/scripts/keep-loaded.sh" keep-loaded.so
export TSAN_OPTIONS="halt_on_error=1 exitcode=66 second_deadlock_stack=1 suppressions=$work/suppressions.txt"
failures=0
# run CODE DESCRIPTION -- command...: the command's exit code must be CODE, its output free of TSan reports.
run() {
    local want="$1" what="$2"
    shift 3
    local output got=0
    output=$(LD_PRELOAD="$work/keep-loaded.so" "$@" 2>&1) || got=$?
    if [ "$got" -ne "$want" ] || [[ "$output" == *ThreadSanitizer* ]]; then
        echo "FAIL: $what: exit $got, wanted $want"
        echo "$output" | head -60 | sed 's/^/    /'
        failures=$((failures + 1))
    else
        echo "ok: $what"
    fi
}
AE=(--set autoExposure.enabled=true --tonemap aces-fitted --decode-threads 0)

run 0 "scene tabletop, EXR frames" -- \
    "$photopic" scene tabletop --format exr --size 640x360 --frames 12 -o flat
run 0 "scene orbit, EXR frames with depth and motion" -- \
    "$photopic" scene orbit --format exr --size 640x360 --frames 8 -o orbit
run 0 "scene testbed, ray-traced truth" -- \
    "$photopic" scene testbed --truth color --size 160x90 --frames 2 -o testbed
for n in 2 3 4; do
    run 0 "tabletop sequence, $n frames in flight" -- \
        "$photopic" image 'flat/frame_%04d.exr' -o "png$n/" "${AE[@]}" --frames-in-flight "$n" -q
done
run 0 "orbit sequence with TAA, 4 frames in flight" -- "$photopic" image 'orbit/scene_%04d.exr' -o taa/ \
    "${AE[@]}" --set aa.mode=taa --frames-in-flight 4 -q
run 0 "EXR outputs" -- "$photopic" image 'flat/frame_%04d.exr' -o exr/ --format exr "${AE[@]}" -q
run 0 "JPEG outputs" -- "$photopic" image 'flat/frame_%04d.exr' -o jpg/ --format jpg "${AE[@]}" -q
run 0 "16-bit TIFF outputs" -- "$photopic" image 'flat/frame_%04d.exr' -o tif/ --format tif --bit-depth 16 \
    "${AE[@]}" -q
cp -r flat broken && head -c 2000 flat/frame_0006.exr > broken/frame_0006.exr
run 2 "a sequence whose seventh frame is cut short" -- \
    "$photopic" image 'broken/frame_%04d.exr' -o stopped/ "${AE[@]}" --frames-in-flight 4 -q
if [ -e stopped ]; then
    echo "FAIL: the stopped run left stopped/ behind"
    failures=$((failures + 1))
fi

if [ "$failures" -ne 0 ]; then
    echo "$failures run(s) failed"
    exit 1
fi
echo "no ThreadSanitizer report"

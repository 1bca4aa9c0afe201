#!/usr/bin/env bash
# Every figure the performance targets are judged by on a GPU, in one run, into OUT/ (a run on an H100 or H200
# takes about five minutes):
#   info.txt                      the device, driver and context (`photopic info`)
#   gl-tests.log                  with GL_TESTS set: the GL suite, which fails on any driver performance warning
#   bench-SIZE-submitted.*        the default chain as the CLI submits it (JSON and table)
#   bench-SIZE-queued.*           the same with --queue-ahead: the GPU's own work, not its waits for the CPU
#   bench-SIZE-rgba16f.*          queued, the scene colour in half floats as renderers hand it over
#   bench-SIZE-natural[-rgba16f].* queued, a photograph (NATURAL) mirrored to the size instead of the synthetic
#                                 frame, whose flat areas a GPU that compresses memory moves for less
#   bench-1920x1080-gl-debug.txt  a KHR_debug context: the driver's messages are in the log
#   ae-histogram-1920x1080.*      queued, histogram metering with auto exposure
#   aa-MODE-1920x1080.*           queued, each anti-aliasing method's passes (fxaa, smaa, taa, taa+smaa)
#   3d-all-SIZE.*                 queued, every 3D effect at once (TAA + SMAA, GTAO, contact shadows, SSR, DoF,
#                                 motion blur, outline, volumetric light): the 3D chain's per-pass times
#   gtao-PRESET-SIZE.*            queued, GTAO alone at each preset (low, medium, high, ultra)
#   gtao-PRESET-mips-SIZE.*       the same with ssao.sampleMips (far steps from the surface pyramid)
#   3d-EFFECT-PRESET-SIZE.*       queued, each other 3D effect alone at each of its presets (contact shadows,
#                                 SSR, volumetric light and motion blur: low, medium, high, ultra; DoF: low,
#                                 medium, high; SMAA: low, high, ultra); SSR over the frame's floor (--floor),
#                                 motion blur on a moving frame (--motion 8), DoF with every pixel far-blurred
#   3d-outline-SIZE.*             queued, the outline alone
#   3d-taa-FILTER-SIZE.*          queued, TAA alone with each history filter (catmull-rom, bilinear)
#   cycles-EFFECT-PRESET.*        with CYCLES set (a folder scripts/bench-cycles.sh rendered: CYCLES/passes/
#                                 frame_0003.exr and CYCLES/track.json), each 3D effect at each preset on that
#                                 Cycles frame's own depth, normals, motion and camera
#   cli.txt                       `photopic image` over a 1080p EXR sequence (AE + bloom + ACES): wall time and,
#                                 from -v, the median milliseconds a frame spends in each stage
# Usage: scripts/gpu-figures.sh OUT PHOTOPIC...   PHOTOPIC is the command that runs photopic (a path, or a
# wrapper and its arguments). Environment: GL_TESTS (the command that runs photopic_gl_tests; unset: skipped),
# FRAMES (timed bench frames, 200), SIZES ("1920x1080 3840x2160"), SEQ_FRAMES (48), SEQ_SIZE
# (1920x1080), NATURAL (data/GoldenGate.exr: run from the repository's root), CYCLES (unset: skipped). On a software renderer, FRAMES=3 SIZES=320x180 SEQ_FRAMES=4 SEQ_SIZE=320x180 checks
# that the script runs; its figures mean nothing there.
set -uo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 OUT PHOTOPIC..." >&2
    exit 2
fi
out=$1
shift
photopic=("$@")
frames=${FRAMES:-200}
read -r -a sizes <<< "${SIZES:-1920x1080 3840x2160}"
seq_frames=${SEQ_FRAMES:-48}
seq_size=${SEQ_SIZE:-1920x1080}
natural=${NATURAL:-data/GoldenGate.exr}
mkdir -p "$out"
failures=0

# Runs one command, its output into OUT/NAME.txt; a failure is counted and named, and the rest still runs.
step() {
    local name=$1 rc=0
    shift
    echo "== $name"
    "$@" > "$out/$name.txt" 2>&1 || rc=$?
    if [ "$rc" -ne 0 ]; then
        echo "   failed (exit $rc): $out/$name.txt" >&2
        failures=$((failures + 1))
    fi
}

bench() {
    local name=$1
    shift
    step "$name" "${photopic[@]}" bench --frames "$frames" --warmup 20 --json "$out/$name.json" "$@"
}

step info "${photopic[@]}" info
if [ -n "${GL_TESTS:-}" ]; then
    echo "== gl-tests"
    # shellcheck disable=SC2086 # GL_TESTS is a command line
    if ! $GL_TESTS > "$out/gl-tests.log" 2>&1; then
        echo "   failed: $out/gl-tests.log" >&2
        failures=$((failures + 1))
    fi
fi
for size in "${sizes[@]}"; do
    bench "bench-$size-submitted" --size "$size"
    bench "bench-$size-queued" --size "$size" --queue-ahead
    bench "bench-$size-rgba16f" --size "$size" --queue-ahead --input-format rgba16f
    # A natural image mirrored to the size: no large flat areas for a GPU's memory compression to take.
    bench "bench-$size-natural" --size "$size" --queue-ahead --input "$natural"
    bench "bench-$size-natural-rgba16f" --size "$size" --queue-ahead --input "$natural" --input-format rgba16f
done
step bench-1920x1080-gl-debug "${photopic[@]}" bench --size 1920x1080 --frames 20 --gl-debug -v
bench ae-histogram-1920x1080 --size 1920x1080 --queue-ahead --set autoExposure.enabled=true \
    --set autoExposure.metering=histogram
for mode in fxaa smaa taa taa+smaa; do
    bench "aa-${mode/+/-}-1920x1080" --size 1920x1080 --queue-ahead --set aa.mode="$mode"
done
all3d=(--set aa.mode=taa+smaa --set ssao.enabled=true --set contactShadows.enabled=true --set ssr.enabled=true
    --set dof.enabled=true --set motionBlur.enabled=true --set outline.enabled=true
    --set volumetricLight.enabled=true)
for size in "${sizes[@]}"; do
    bench "3d-all-$size" --size "$size" --queue-ahead "${all3d[@]}"
    for preset in low medium high ultra; do
        bench "gtao-$preset-$size" --size "$size" --queue-ahead --set ssao.enabled=true --set ssao.quality="$preset"
        bench "gtao-$preset-mips-$size" --size "$size" --queue-ahead --set ssao.enabled=true \
            --set ssao.quality="$preset" --set ssao.sampleMips=true
    done
    # The frame as each effect needs it to do its work: SSR over a floor (long rays), motion blur (and TAA)
    # on a moving frame, depth of field with every pixel far-blurred.
    for effect in contactShadows ssr volumetricLight motionBlur; do
        frame=()
        [ "$effect" = ssr ] && frame=(--floor)
        [ "$effect" = motionBlur ] && frame=(--motion 8)
        for preset in low medium high ultra; do
            bench "3d-$effect-$preset-$size" --size "$size" --queue-ahead "${frame[@]}" \
                --set "$effect.enabled=true" --set "$effect.quality=$preset"
        done
    done
    for preset in low medium high; do
        bench "3d-dof-$preset-$size" --size "$size" --queue-ahead --set dof.enabled=true --set dof.quality="$preset" \
            --set dof.mode=artistic --set dof.focalDistance=2 --set dof.bokehRadius=8
    done
    for preset in low high ultra; do
        bench "3d-smaa-$preset-$size" --size "$size" --queue-ahead --set aa.mode=smaa --set smaa.quality="$preset"
    done
    bench "3d-outline-$size" --size "$size" --queue-ahead --set outline.enabled=true
    for filter in catmull-rom bilinear; do
        bench "3d-taa-$filter-$size" --size "$size" --queue-ahead --motion 8 --set aa.mode=taa \
            --set taa.historyFilter="$filter"
    done
done
if [ -n "${CYCLES:-}" ]; then
    for effect in ssao contactShadows ssr volumetricLight motionBlur; do
        for preset in low medium high ultra; do
            bench "cycles-$effect-$preset" --input "$CYCLES/passes/frame_0003.exr" --camera "$CYCLES/track.json" \
                --queue-ahead --set "$effect.enabled=true" --set "$effect.quality=$preset"
        done
    done
fi
echo "== cli"
seq_dir=$(mktemp -d)
trap 'rm -rf "$seq_dir"' EXIT
if "${photopic[@]}" scene tabletop --format exr --size "$seq_size" --frames "$seq_frames" -o "$seq_dir/seq" -q \
    > "$out/cli.txt" 2>&1; then
    start=$(date +%s.%N)
    if ! "${photopic[@]}" image "$seq_dir"/seq/frame_*.exr -o "$seq_dir/png/" --set autoExposure.enabled=true \
        --tonemap aces-fitted -v >> "$out/cli.txt" 2>&1; then
        echo "   photopic image failed: $out/cli.txt" >&2
        failures=$((failures + 1))
    fi
    end=$(date +%s.%N)
    awk -v s="$start" -v e="$end" -v n="$seq_frames" \
        'BEGIN { printf "wall %.3f s for %d frames: %.1f ms a frame\n", e - s, n, 1000 * (e - s) / n }' \
        >> "$out/cli.txt"
    tail -n 2 "$out/cli.txt"
else
    echo "   the sequence could not be written: $out/cli.txt" >&2
    failures=$((failures + 1))
fi
echo "$failures step(s) failed; the figures are in $out"
[ "$failures" -eq 0 ]

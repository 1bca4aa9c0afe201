#!/usr/bin/env bash
# How far a chunk's frames are from the single run's when its histories (TAA, SSR, volumetric light, motion
# blur's previous frame) start at the chunk's border: the testbed sequence with auto exposure (planned once,
# --exposure-track) and TAA, rendered whole and as one chunk from BORDER with --preroll N for each N.
#
#     scripts/farm-residual.sh [PHOTOPIC] [FIXTURE] [OUT]     (defaults: build/release's binaries, /tmp/farm-residual)
#
# The testbed's cut (its telemetry's cut column) is declared with --cut, as a TD declares a shot's cuts: the
# histories restart there in both runs. Environment: FRAMES (112), SIZE (320x180), BORDER (80), PREROLLS ("0 8 16 32"), EXTRA (more photopic image
# options, e.g. "--set motionBlur.enabled=true"). Prints, per N, the border frame's mean and maximum difference in
# 8-bit code values, the share of its pixels more than 2 off, and the worst frame of the chunk.
set -euo pipefail
PHOTOPIC=${1:-build/release/photopic}
FIX=${2:-build/release/tests/e2e/photopic_farm_fixture}
OUT=${3:-/tmp/farm-residual}
FRAMES=${FRAMES:-112}
SIZE=${SIZE:-320x180}
BORDER=${BORDER:-80}
PREROLLS=${PREROLLS:-0 8 16 32}
read -r -a EXTRA <<< "${EXTRA:-}"
AE=(--set autoExposure.enabled=true --fps 24)
TAA=(--set aa.mode=taa --jitter halton)

rm -rf "$OUT" && mkdir -p "$OUT"
LOG="$OUT/photopic.log"
"$PHOTOPIC" scene testbed -o "$OUT/tb" --frames "$FRAMES" --size "$SIZE" -q >> "$LOG"
IN="$OUT/tb/scene_%04d.exr"
last=$((FRAMES - 1))
CUTS=()
for cut in $(awk -F, 'NR > 1 && $4 == 1 { print $1 }' "$OUT/tb/telemetry.csv"); do
    CUTS+=(--cut "$cut")
done
"$PHOTOPIC" meter "$IN" "${AE[@]}" -q -o "$OUT/meter.csv" >> "$LOG"
"$PHOTOPIC" expose "$OUT/meter.csv" "${AE[@]}" "${CUTS[@]}" -q -o "$OUT/exposure.csv" >> "$LOG"
"$PHOTOPIC" image "$IN" "${AE[@]}" "${TAA[@]}" "${EXTRA[@]}" --exposure-track "$OUT/exposure.csv" -q \
    -o "$OUT/single/f%04d.png" >> "$LOG"
# Only the chunk's frames are compared: the single run's copy of them.
mkdir -p "$OUT/single-chunk"
for ((f = BORDER; f <= last; ++f)); do
    cp "$OUT/single/$(printf 'f%04d.png' "$f")" "$OUT/single-chunk/"
done
border=$(printf 'f%04d.png' "$BORDER")
echo "testbed $FRAMES frames at $SIZE, cuts: ${CUTS[*]:-none}; a chunk from frame $BORDER, 8-bit code values"
printf '%-8s %-12s %-10s %-12s %s\n' preroll border_mean border_max border_over2 "chunk_worst_mean (frame)"
for n in $PREROLLS; do
    "$PHOTOPIC" image "$IN" --frames "$BORDER-$last" --preroll "$n" "${AE[@]}" "${TAA[@]}" "${EXTRA[@]}" \
        --exposure-track "$OUT/exposure.csv" -q -o "$OUT/chunk-$n/f%04d.png" >> "$LOG"
    report=$("$FIX" "$OUT/single-chunk" "$OUT/chunk-$n")
    awk -v n="$n" -v border="$border" '
        $1 == "frame" && $2 == border { mean = $4; max = $6; over = $8 }
        $1 == "all" { worst = $7; frame = $9 }
        END { printf "%-8s %-12s %-10s %-12s %s (%s)\n", n, mean, max, over, worst, frame }' <<< "$report"
done

#!/usr/bin/env bash
# A sequence split into chunks gives the single run's frames: each frame metered apart (photopic meter), the
# exposure planned over the whole sequence (photopic expose), each chunk rendered with that plan
# (--exposure-track) and the frames before it (--preroll). No scheduler here: farm.sh runs the same stages
# through Slurm.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
FIX="${PHOTOPIC_FARM_FIXTURE:?built by CMake}"
AE=(--set autoExposure.enabled=true --fps 24)

expect 0 "a 24-frame testbed sequence" -- "$PHOTOPIC" scene testbed -o "$S/tb" --frames 24 --size 96x54
IN="$S/tb/scene_%04d.exr"

# Metering: chunks merge into the whole sequence's metering.
expect 0 "meter the whole sequence" -- "$PHOTOPIC" meter "$IN" "${AE[@]}" -o "$S/meter-all.csv"
check "one row per frame, after the two header lines" test "$(wc -l < "$S/meter-all.csv")" -eq 26
expect 0 "meter frames 0-11" -- "$PHOTOPIC" meter "$IN" --frames 0-11 "${AE[@]}" -o "$S/meter-a.csv"
expect 0 "meter frames 12-23" -- "$PHOTOPIC" meter "$IN" --frames 12-23 "${AE[@]}" -o "$S/meter-b.csv"
check "the chunks' rows are the whole run's" bash -c \
    'diff <(tail -n +3 "$1") <(tail -n +3 "$2"; tail -n +3 "$3")' _ "$S/meter-all.csv" "$S/meter-a.csv" "$S/meter-b.csv"

# Planning: the chunks' files, in any order, plan the same track as the whole run's file.
expect 0 "plan from the whole run's meter file" -- "$PHOTOPIC" expose "$S/meter-all.csv" "${AE[@]}" -o "$S/exp-all.csv"
check "says how long planning took" contains "planned in"
expect 0 "plan from the chunks' files" -- "$PHOTOPIC" expose "$S/meter-b.csv" "$S/meter-a.csv" "${AE[@]}" \
    -o "$S/exp.csv"
check "the same track" cmp -s "$S/exp-all.csv" "$S/exp.csv"
check "the first frame snaps (cut 1)" test "$(sed -n 3p "$S/exp.csv" | cut -d, -f3)" = 1
expect 2 "a chunk's file left out is a gap" -- "$PHOTOPIC" expose "$S/meter-b.csv" "${AE[@]}" -o "$S/x.csv" \
    --cut 3
check "says which frames are missing" contains "not a metered frame"
expect 2 "a missing middle chunk" -- bash -c "head -8 '$S/meter-a.csv' > '$S/meter-short.csv' &&
    '$PHOTOPIC' expose '$S/meter-short.csv' '$S/meter-b.csv' --set autoExposure.enabled=true -o '$S/x.csv'"
check "names the first missing frame" contains "the first 6"
expect 2 "metering of another mode" -- "$PHOTOPIC" expose "$S/meter-all.csv" "${AE[@]}" \
    --set autoExposure.metering=histogram -o "$S/x.csv"
check "says to meter again" contains "meter again"
expect 2 "expose without auto exposure" -- "$PHOTOPIC" expose "$S/meter-all.csv" -o "$S/x.csv"
check "names the key" contains "autoExposure.enabled"
check "no track written by the failures" test ! -e "$S/x.csv"

# Rendering: chunks with the track are the single run's bytes; the GPU's own adaptation within a code value.
expect 0 "the single run with the track" -- "$PHOTOPIC" image "$IN" "${AE[@]}" --exposure-track "$S/exp.csv" \
    -o "$S/track/f%04d.png" --telemetry "$S/track.csv"
expect 0 "chunk 0-11 with the track" -- "$PHOTOPIC" image "$IN" --frames 0-11 "${AE[@]}" \
    --exposure-track "$S/exp.csv" -o "$S/chunked/f%04d.png"
expect 0 "chunk 12-23 with the track and a preroll" -- "$PHOTOPIC" image "$IN" --frames 12-23 --preroll 4 \
    "${AE[@]}" --exposure-track "$S/exp.csv" -o "$S/chunked/f%04d.png" --telemetry "$S/chunk-b.csv"
check "the preroll's frames are not written" test "$(ls "$S"/chunked/*.png | wc -l)" -eq 24
check "every frame the single run's bytes" bash -c \
    'for f in "$1"/*.png; do cmp -s "$f" "$2/$(basename "$f")" || exit 1; done' _ "$S/track" "$S/chunked"
check "the chunk's telemetry keeps the input's frame numbers, from 12" \
    test "$(sed -n 2p "$S/chunk-b.csv" | cut -d, -f1,2)" = "12,0.500000"
check "and no row for the preroll" test "$(wc -l < "$S/chunk-b.csv")" -eq 13
check "the track's applied EV is what the frames got" bash -c \
    'test -s "$2" && diff <(tail -n +3 "$1" | cut -d, -f6) <(tail -n +2 "$2" | cut -d, -f5)' _ "$S/exp.csv" \
    "$S/track.csv"
expect 0 "the single run with the GPU's own adaptation" -- "$PHOTOPIC" image "$IN" "${AE[@]}" -o "$S/gpu/f%04d.png"
expect 0 "compare it with the track's run" -- "$FIX" "$S/gpu" "$S/track"
echo "$OUTPUT" | tail -1
check "within one code value everywhere" test "$(awk '/^all/ {print $5}' <<< "$OUTPUT")" -le 1

# TAA across a chunk border: the default preroll warms the history.
TAA=(--set aa.mode=taa --jitter halton)
expect 0 "the single TAA run" -- "$PHOTOPIC" image "$IN" "${AE[@]}" "${TAA[@]}" --exposure-track "$S/exp.csv" \
    -o "$S/taa/f%04d.png"
for range in 0-11 12-23; do
    expect 0 "TAA chunk $range, preroll 24" -- "$PHOTOPIC" image "$IN" --frames "$range" --preroll 24 "${AE[@]}" \
        "${TAA[@]}" --exposure-track "$S/exp.csv" -o "$S/taa-chunks/f%04d.png"
done
expect 0 "compare TAA chunks with the single run" -- "$FIX" "$S/taa" "$S/taa-chunks"
echo "$OUTPUT" | grep -E "f0012|^all"
check "the border frame within 1 code value mean" \
    awk '/f0012/ { seen = 1; ok = $4 <= 1.0 } END { exit !(seen && ok) }' <<< "$OUTPUT"

# Bad input.
expect 2 "a frame the track lacks" -- "$PHOTOPIC" image "$IN" "${AE[@]}" --exposure-track "$S/meter-a.csv" \
    -o "$S/bad/f%04d.png"
check "says it is not a track" contains "not a file of this kind"
expect 2 "a track without the chunk's frames" -- bash -c "head -10 '$S/exp.csv' > '$S/short.csv' &&
    '$PHOTOPIC' image '$IN' --frames 12-23 --exposure-track '$S/short.csv' -o '$S/bad/f%04d.png'"
check "names the frame" contains "frame 12 is not in the track"
expect 2 "--preroll over a list of files" -- "$PHOTOPIC" image "$S/tb/scene_0001.exr" "$S/tb/scene_0002.exr" \
    --preroll 2 -o "$S/bad/"
check "says it needs a pattern" contains "frame-numbered pattern"
check "nothing written by the failures" test ! -e "$S/bad"

finish

#!/usr/bin/env bash
# Auto exposure from the CLI: image sequences with --telemetry (one CSV row per frame), --debug views, and the
# errors a user can make (unknown view, unreadable mask).
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"

# Frames in name order: a dark frame then three bright ones (the same files under sequence names).
mkdir -p "$S/frames" "$S/out"
ln -s "$DATA/Desk.hdr" "$S/frames/f0.hdr"
for i in 1 2 3; do ln -s "$DATA/GoldenGate.exr" "$S/frames/f$i.exr"; done
AE=(--set autoExposure.enabled=true --set autoExposure.minEV=-8 --set autoExposure.maxEV=8)

expect 0 "sequence with telemetry" -- "$PHOTOPIC" image "$S"/frames/f3.exr "$S"/frames/f1.exr "$S"/frames/f0.hdr \
    "$S"/frames/f2.exr -o "$S/out" --fps 10 --telemetry "$S/t.csv" "${AE[@]}"
check "telemetry written" test -s "$S/t.csv"
check "issue's columns first" test "$(head -1 "$S/t.csv" | cut -d, -f1-6)" = "frame,time_s,measured_luma,target_log2,applied_log2,exposure"
check "one row per frame" test "$(tail -n +2 "$S/t.csv" | wc -l)" -eq 4
check "frames in order" test "$(tail -n +2 "$S/t.csv" | cut -d, -f1 | tr '\n' ' ')" = "0 1 2 3 "
check "time from --fps" test "$(sed -n 4p "$S/t.csv" | cut -d, -f2)" = "0.200000"
check "every value finite" bash -c "! grep -qiE 'nan|inf' '$S/t.csv'"
# Frame 1 is the first GoldenGate frame (different size: a resize snaps); frames 2 and 3 keep it, so
# applied_log2 stays equal to the target; frame 0 snaps too (first frame).
check "first frame snaps" awk -F, 'NR == 2 { exit !($4 == $5) }' "$S/t.csv"
check "each row has its own measured luminance" awk -F, 'NR == 2 { a = $3 } NR == 3 { exit !(a != $3) }' "$S/t.csv"
check "exposure is 2^applied (manual 0)" awk -F, 'NR > 1 { d = $6 - 2 ^ $5; if (d > 1e-4 * $6 || -d > 1e-4 * $6) exit 1 }' "$S/t.csv"

expect 0 "same-size sequence adapts over time" -- "$PHOTOPIC" image "$S"/frames/f1.exr "$DATA/Desk.exr" \
    -o "$S/out2" --telemetry "$S/t2.csv" --set autoExposure.enabled=true --set tonemapping.exposure=1
check "manual EV multiplies: exposure = 2^(1 + applied)" awk -F, 'NR > 1 { d = $6 - 2 ^ (1 + $5); if (d > 1e-4 * $6 || -d > 1e-4 * $6) exit 1 }' "$S/t2.csv"

for view in exposure luma ev metering histogram bloom; do
    expect 0 "--debug $view" -- "$PHOTOPIC" image "$DATA/Desk.hdr" -o "$S/debug-$view.png" --debug "$view" "${AE[@]}"
    check "$view view written" test -s "$S/debug-$view.png"
done
check "bloom view with bloom on (the default) does not warn" bash -c '! grep -q "no bloom" <<< "$0"' "$OUTPUT"
expect 0 "--debug bloom with bloom off" -- "$PHOTOPIC" image "$DATA/Desk.hdr" -o "$S/debug-nobloom.png" \
    --debug bloom --set bloom.enabled=false
check "bloom view without bloom says so" contains "no bloom"
expect 0 "histogram view with auto exposure off" -- "$PHOTOPIC" image "$DATA/Desk.hdr" -o "$S/hist-off.png" \
    --debug histogram --telemetry "$S/t3.csv"
check "histogram counted with auto exposure off" awk -F, 'NR == 2 { exit !($11 == 644 * 874) }' "$S/t3.csv"

expect 2 "unknown debug view" -- "$PHOTOPIC" image "$DATA/Desk.hdr" -o "$S/bad.png" --debug sparkles
check "error names the key" contains "postEffects.debug.view"
check "allowed views listed" contains "histogram"
check "and the option as typed" contains "invalid settings in --debug sparkles"
check "no output for a bad view" test ! -e "$S/bad.png"

expect 2 "unreadable metering mask" -- "$PHOTOPIC" image "$DATA/Desk.hdr" -o "$S/mask.png" \
    --set autoExposure.enabled=true --set autoExposure.metering=mask --set "autoExposure.mask.path=$S/nomask.png"
check "error names the mask file" contains "nomask.png"
check "no output for a bad mask" test ! -e "$S/mask.png"

expect 2 "telemetry into a missing folder (checked before any work)" -- "$PHOTOPIC" image "$DATA/Desk.hdr" \
    -o "$S/ok.png" --telemetry "$S/missing/t.csv"
check "no partial telemetry" test ! -e "$S/missing/t.csv"
check "no image from the refused run" test ! -e "$S/ok.png"

finish

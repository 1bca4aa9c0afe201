#!/usr/bin/env bash
# `photopic demo`: the tabletop walk at a tiny size (keeps the test fast on llvmpipe): frames, telemetry.csv
# with issue 5's columns first, the plot, the contact sheet and a summary of both crossings.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"

expect 0 "demo renders the walk" -- "$PHOTOPIC" demo -o "$S/demo" --size 64x36 --fps 15 --seconds 16 --every 2 --no-video
check "frames written" test -s "$S/demo/frame_0000.png" -a -s "$S/demo/frame_0119.png"
check "every 2nd frame only" test ! -e "$S/demo/frame_0120.png"
check "telemetry: one row per frame plus the header" test "$(wc -l < "$S/demo/telemetry.csv")" -eq 241
check "telemetry columns (issue 5's order)" test "$(head -1 "$S/demo/telemetry.csv" | cut -d, -f1-12)" = \
    "frame,time_s,subject,world_x,world_y,screen_u,screen_v,outdoors,measured_luma,target_log2,applied_log2,exposure"
check "plot written" test -s "$S/demo/exposure_plot.png"
check "contact sheet written" test -s "$S/demo/contact_sheet.png"
check "summary: stepping out" contains "step outside"
check "summary: stepping in" contains "step inside"
check "video skipped on request" contains "skipped"
expect 0 "demo -q prints nothing" -- "$PHOTOPIC" demo -o "$S/quiet" --size 32x18 --fps 5 --seconds 2 --no-video -q
check "nothing printed under -q" test -z "$OUTPUT"
expect 2 "bad demo size" -- "$PHOTOPIC" demo -o "$S/bad" --size 12by7
check "size named" contains "12by7"

finish

#!/usr/bin/env bash
# The canvas scene: frames and telemetry columns, motion and material files, their errors.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"

expect 0 "scene --list names canvas" -- "$PHOTOPIC" scene --list
check "canvas listed" contains "canvas"
expect 0 "canvas renders" -- "$PHOTOPIC" scene canvas -o "$S/c" --frames 3 --size 256x144
check "frames written" test -s "$S/c/frame_0000.png" -a -s "$S/c/frame_0002.png"
check "telemetry has a header and 3 rows" test "$(wc -l < "$S/c/telemetry.csv")" -eq 4
check "telemetry columns: the scene's, then the exposure's" test "$(head -1 "$S/c/telemetry.csv" | cut -d, -f1-14)" = \
    "frame,time_s,pitch,roll,yaw,light_x,light_y,light_z,tiles_shaded,tiles_total,measured_luma,target_log2,applied_log2,exposure"
check "frame 0 is level: light (0, 0, -1)" test "$(sed -n 2p "$S/c/telemetry.csv" | cut -d, -f6-8)" = "0,0,-1"

printf 'time_s,pitch,roll,yaw\n0,0,-0.3,0\n1,0.2,0.3,0.5\n' > "$S/good.csv"
expect 0 "--motion CSV" -- "$PHOTOPIC" scene canvas -o "$S/m" --frames 2 --fps 1 --size 128x72 --motion "$S/good.csv" \
    --set canvas.tileSize=32 --set canvas.occupancy=0.25
check "motion drives the telemetry (frame 1: pitch 0.2, roll 0.3, yaw 0.5)" \
    test "$(sed -n 3p "$S/m/telemetry.csv" | cut -d, -f3-5)" = "0.2,0.3,0.5"
check "a quarter of the 4 x 3 tiles shaded" test "$(sed -n 2p "$S/m/telemetry.csv" | cut -d, -f9-10)" = "3,12"

printf 'time_s,pitch,roll,yaw\n0,0,0,0\n0.5,0.1,x,0\n' > "$S/bad.csv"
expect 2 "malformed motion CSV" -- "$PHOTOPIC" scene canvas -o "$S/bad" --frames 1 --size 64x36 --motion "$S/bad.csv"
check "error names the file and line" contains "bad.csv:3:"
check "nothing written for a bad motion file" test ! -e "$S/bad/frame_0000.png"

echo "not a png" > "$S/material.png"
expect 2 "malformed material image" -- "$PHOTOPIC" scene canvas -o "$S/badm" --frames 1 --size 64x36 \
    --material "$S/material.png"
check "error names the material file" contains "material.png"
expect 2 "--motion on another scene" -- "$PHOTOPIC" scene gradient -o "$S/g" --frames 1 --motion "$S/good.csv"
check "says it belongs to canvas" contains "canvas"
expect 2 "bad shading mode" -- "$PHOTOPIC" scene canvas -o "$S/s" --frames 1 --set canvas.shading=deferred
check "shading named" contains "canvas.shading"
expect 2 "tile size not a multiple of 16" -- "$PHOTOPIC" scene canvas -o "$S/t" --frames 1 --set canvas.tileSize=100
check "tileSize named" contains "canvas.tileSize"

finish

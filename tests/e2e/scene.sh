#!/usr/bin/env bash
# The scene runner: frames, telemetry.csv, scene settings through --set NAME.key=value, errors.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"

expect 0 "scene --list" -- "$PHOTOPIC" scene --list
check "lists the gradient scene" contains "gradient"
expect 0 "gradient scene renders" -- "$PHOTOPIC" scene gradient -o "$S/grad" --frames 4 --size 96x54 --set gradient.period=2
check "frames written" test -s "$S/grad/frame_0000.png" -a -s "$S/grad/frame_0003.png"
check "telemetry written" test -s "$S/grad/telemetry.csv"
check "telemetry has one row per frame plus the header" test "$(wc -l < "$S/grad/telemetry.csv")" -eq 5
check "telemetry starts with frame,time_s" test "$(head -c 12 "$S/grad/telemetry.csv")" = "frame,time_s"
expect 0 "EXR frames" -- "$PHOTOPIC" scene gradient -o "$S/grad-exr" --frames 1 --size 64x36 --format exr
check "EXR frame written" test -s "$S/grad-exr/frame_0000.exr"
expect 0 "tabletop scene renders" -- "$PHOTOPIC" scene tabletop -o "$S/tt" --frames 3 --size 96x54 --set tabletop.darkness=0.5
check "tabletop frames written" test -s "$S/tt/frame_0002.png"
# Frames are read back a frame late and written on worker threads: each file still holds its own frame, in
# 8 and 16 bits and as EXR, with --every too.
for format in png16 exr; do
    ext=${format%16}
    depth=$([ "$format" = png16 ] && echo "--bit-depth 16" || true)
    # shellcheck disable=SC2086 # $depth is one option and its value, or nothing
    expect 0 "tabletop $format frames" -- "$PHOTOPIC" scene tabletop -o "$S/tt-$format" --frames 3 --size 96x54 \
        --set tabletop.darkness=0.5 --format "$ext" $depth
    # shellcheck disable=SC2086
    expect 0 "tabletop $format, every other frame" -- "$PHOTOPIC" scene tabletop -o "$S/tt-$format-every" \
        --frames 3 --size 96x54 --set tabletop.darkness=0.5 --format "$ext" $depth --every 2
    check "$format: frames 0 and 2 of the run are --every 2's 0 and 1" \
        cmp -s "$S/tt-$format/frame_0002.$ext" "$S/tt-$format-every/frame_0001.$ext"
    check "$format: the first frames agree" cmp -s "$S/tt-$format/frame_0000.$ext" "$S/tt-$format-every/frame_0000.$ext"
    check "$format: --every 2 wrote two frames of three" test ! -e "$S/tt-$format-every/frame_0002.$ext"
done
expect 0 "tabletop, one EXR frame" -- "$PHOTOPIC" scene tabletop -o "$S/tt-one" --frames 1 --size 96x54 \
    --set tabletop.darkness=0.5 --format exr
check "a one-frame run's frame is the longer run's first" cmp -s "$S/tt-one/frame_0000.exr" "$S/tt-exr/frame_0000.exr"
check "frames differ from each other (so the comparisons above could fail)" \
    bash -c "! cmp -s '$S/tt-exr/frame_0000.exr' '$S/tt-exr/frame_0002.exr'"
check "tabletop telemetry columns (issue 5's order)" test "$(head -1 "$S/tt/telemetry.csv" | cut -d, -f1-12)" = \
    "frame,time_s,subject,world_x,world_y,screen_u,screen_v,outdoors,measured_luma,target_log2,applied_log2,exposure"
expect 2 "unknown scene" -- "$PHOTOPIC" scene nowhere -o "$S/x" --frames 1
check "known scenes listed" contains "known scenes"
expect 2 "bad scene setting" -- "$PHOTOPIC" scene gradient -o "$S/y" --frames 1 --set gradient.period=0
check "scene setting named by path" contains "gradient.period"
expect 2 "bad size" -- "$PHOTOPIC" scene gradient -o "$S/z" --size 12by7
check "size named" contains "12by7"
check "nothing written for bad input" test ! -e "$S/y/frame_0000.png" -a ! -e "$S/z/frame_0000.png"

finish

#!/usr/bin/env bash
# The testbed scene: display PNGs plus the scene-referred EXR frames `photopic image` reads back, and the
# ray tracer's references (--truth).
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"

expect 0 "testbed renders" -- "$PHOTOPIC" scene testbed -o "$S/tb" --frames 3 --size 96x54
check "display frames written" test -s "$S/tb/frame_0000.png" -a -s "$S/tb/frame_0002.png"
check "scene EXR frames written" test -s "$S/tb/scene_0000.exr" -a -s "$S/tb/scene_0002.exr"
check "telemetry has shot and cut columns" test "$(head -1 "$S/tb/telemetry.csv" | cut -d, -f1-4)" = "frame,time_s,shot,cut"
expect 0 "image --info reads the scene EXR" -- "$PHOTOPIC" image --info "$S/tb/scene_0002.exr"
check "depth found" contains "Z -> depth"
check "normals found" contains "N.X -> normals"
check "motion found" contains "motion.X -> motion"
check "camera found" contains "worldToNDC"
expect 0 "the testbed's EXR sequence renders through photopic image with its 3D layers" -- \
    "$PHOTOPIC" image "$S"/tb/scene_*.exr -o "$S/img/" --write-aux "$S/aux" --debug motion
check "one image per frame" test "$(ls "$S"/img/*.png | wc -l)" -eq 3
check "the decoded layers written back" test -s "$S/aux/scene_0002.aux.exr"
check "no input problem reported" bash -c "! grep -qi 'ignored\|skipped' <<< \"\$1\"" _ "$OUTPUT"

expect 0 "testbed with TAA writes jittered scene EXRs" -- "$PHOTOPIC" scene testbed -o "$S/tbtaa" --frames 4 \
    --size 96x54 --set aa.mode=taa
expect 0 "image --info finds their jitter" -- "$PHOTOPIC" image --info "$S/tbtaa/scene_0002.exr"
check "jitter attribute listed" contains "jitter (v2f) -> sample jitter"
expect 0 "TAA over the jittered sequence" -- "$PHOTOPIC" image "$S"/tbtaa/scene_*.exr -o "$S/taa/" --set aa.mode=taa
check "no warning that the frames are unjittered" bash -c "! grep -q 'not jittered' <<< \"\$1\"" _ "$OUTPUT"
expect 0 "TAA over unjittered frames" -- "$PHOTOPIC" image "$S"/tb/scene_*.exr -o "$S/taa2/" --set aa.mode=taa
check "says once that TAA can only filter over time" contains "not jittered"
expect 0 "--jitter halton takes Photopic's own sequence" -- "$PHOTOPIC" image "$S"/tb/scene_*.exr -o "$S/taa3/" \
    --set aa.mode=taa --jitter halton
check "then no warning" bash -c "! grep -q 'not jittered' <<< \"\$1\"" _ "$OUTPUT"
expect 0 "TAA on a single image" -- "$PHOTOPIC" image "$S/tb/scene_0002.exr" -o "$S/one.png" --set aa.mode=taa
check "says TAA is off for a single image" contains "a single image has no earlier frames"
check "in one warning" test "$(grep -c 'warning' <<< "$OUTPUT")" -eq 1
expect 0 "TAA + SMAA on a single image" -- "$PHOTOPIC" image "$S/tb/scene_0002.exr" -o "$S/one-smaa.png" \
    --set aa.mode=taa+smaa
check "SMAA still runs" contains "smaa runs"
expect 0 "SMAA alone on the same image" -- "$PHOTOPIC" image "$S/tb/scene_0002.exr" -o "$S/one-smaa-only.png" \
    --set aa.mode=smaa
check "the same image as taa+smaa gives" cmp -s "$S/one-smaa.png" "$S/one-smaa-only.png"
expect 0 "SSAA on images" -- "$PHOTOPIC" image "$S/tb/scene_0002.exr" -o "$S/one-ssaa.png" --set aa.mode=ssaa
check "says SSAA is off for images, in one warning" test "$(grep -c 'SSAA renders each frame' <<< "$OUTPUT")" -eq 1
check "and nothing else" test "$(grep -c 'warning' <<< "$OUTPUT")" -eq 1

expect 0 "ao truth" -- "$PHOTOPIC" scene testbed --truth ao -o "$S/truth" --frames 1 --start 10 --size 64x36 \
    --set testbed.aoSamples=4
check "ao EXR and preview written" test -s "$S/truth/truth_ao_0010.exr" -a -s "$S/truth/truth_ao_0010.png"
expect 0 "depth truth" -- "$PHOTOPIC" scene testbed --truth depth -o "$S/truth" --frames 1 --size 64x36
expect 0 "image --info reads the depth truth" -- "$PHOTOPIC" image --info "$S/truth/truth_depth_0000.exr"
check "its Z is found" contains "Z -> depth"
expect 2 "unknown truth kind" -- "$PHOTOPIC" scene testbed --truth fog -o "$S/bad" --frames 1 --size 64x36
check "kinds listed" contains "thinlens"
expect 2 "truth of another scene" -- "$PHOTOPIC" scene gradient --truth ao -o "$S/bad2" --frames 1 --size 64x36
check "says it is the testbed's" contains "testbed"

finish

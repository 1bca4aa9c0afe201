#!/usr/bin/env bash
# Motion blur and outline from the CLI: the testbed renders with them (the velocity-tiles view written to EXR
# and PNG), `photopic bench` lists their passes, and bad settings name their key. The view's values are
# checked against the analytic radius in tests/gl/test_motion_blur.cpp.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"

expect 0 "testbed with motion blur and outline" -- "$PHOTOPIC" scene testbed -o "$S/mb" --frames 3 --size 96x54 \
    --set motionBlur.enabled=true --set outline.enabled=true
check "frames written" test -s "$S/mb/frame_0002.png"
check "nothing skipped" bash -c "! grep -qi 'skipped' <<< \"\$1\"" _ "$OUTPUT"
expect 0 "the velocity-tiles view to EXR" -- "$PHOTOPIC" scene testbed -o "$S/tiles" --frames 3 --size 96x54 \
    --format exr --set motionBlur.enabled=true --set debug.view=velocity-tiles
check "view frame written" test -s "$S/tiles/frame_0002.exr"
check "nothing skipped (view)" bash -c "! grep -qi 'skipped' <<< \"\$1\"" _ "$OUTPUT"
expect 0 "motion blur after TAA" -- "$PHOTOPIC" scene testbed -o "$S/late" --frames 3 --size 96x54 \
    --set motionBlur.enabled=true --set motionBlur.placement=after-taa --set aa.mode=taa
check "after-taa frame written" test -s "$S/late/frame_0002.png"

expect 0 "bench lists the passes" -- "$PHOTOPIC" bench --size 128x72 --frames 2 --set motionBlur.enabled=true \
    --set outline.enabled=true
for pass in "motion blur prepare" "motion blur tile max" "motion blur neighbour max" "motion blur gather" outline; do
    check "bench lists '$pass'" contains "$pass"
done

# --motion moves the bench's 3D frame, so the gather has moving tiles to blur; the JSON records it.
expect 0 "bench of a moving frame at a preset" -- "$PHOTOPIC" bench --size 128x72 --frames 2 --motion 6 \
    --set motionBlur.enabled=true --set motionBlur.quality=low --json "$S/moving.json"
check "the motion is in the JSON" python3 -c "import json,sys; \
sys.exit(0 if json.load(open('$S/moving.json'))['motionPixels'] == 6 else 1)"
expect 2 "motion out of range is refused" -- "$PHOTOPIC" bench --size 64x64 --frames 1 --motion -1
check "the option is named" contains "--motion"
expect 2 "the canvas bench has no 3D frame to move" -- "$PHOTOPIC" bench --scene canvas --size 64x64 --frames 1 \
    --motion 4
check "the refusal says why" contains "--motion and --floor change the pipeline's 3D frame only"
expect 2 "an unknown preset names the key" -- "$PHOTOPIC" scene testbed -o "$S/bad4" --frames 1 --size 32x18 \
    --set motionBlur.quality=extreme
check "the key is named (quality)" contains "motionBlur.quality"

expect 2 "maxBlur longer than a tile" -- "$PHOTOPIC" scene testbed -o "$S/bad" --frames 1 --size 32x18 \
    --set motionBlur.maxBlur=40
check "the key is named" contains "motionBlur.maxBlur"
expect 2 "outline width out of range" -- "$PHOTOPIC" scene testbed -o "$S/bad2" --frames 1 --size 32x18 \
    --set outline.width=0
check "the key is named (outline)" contains "outline.width"
expect 2 "an unknown placement" -- "$PHOTOPIC" scene testbed -o "$S/bad3" --frames 1 --size 32x18 \
    --set motionBlur.placement=sideways
check "the key is named (placement)" contains "motionBlur.placement"

finish

#!/usr/bin/env bash
# The orbit scene as a user runs it: frames and scene-referred EXRs, no warnings, the calibration and
# anti-aliasing settings, --model with a real glTF model and each malformed sample refused (exit 2, the file
# and the problem named, nothing written), --env, and `photopic demo --scene orbit`. The measured checks
# (IBL proportionality, HDR bands, one tone mapping, amb/hemi/exp) are GL tests (tests/gl/test_orbit.cpp).
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
BAD="$(dirname "$0")/../data/gltf-bad"

expect 0 "orbit renders" -- "$PHOTOPIC" scene orbit -o "$S/o" --frames 3 --size 96x54
check "display frames written" test -s "$S/o/frame_0000.png" -a -s "$S/o/frame_0002.png"
check "scene EXR frames written" test -s "$S/o/scene_0002.exr"
check "no warning or GL error printed" bash -c "! grep -qi 'warn\|error' <<< \"\$1\"" _ "$OUTPUT"
check "telemetry has the script time and the sun's visibility" \
    test "$(head -1 "$S/o/telemetry.csv" | cut -d, -f1-4)" = "frame,time_s,script_s,sun_visibility"
expect 0 "image --info reads the scene EXR's 3D layers" -- "$PHOTOPIC" image --info "$S/o/scene_0002.exr"
check "depth, normals, motion and camera found" bash -c \
    "grep -q 'Z -> depth' <<< \"\$1\" && grep -q 'N.X -> normals' <<< \"\$1\" && grep -q 'motion.X -> motion' <<< \"\$1\" && grep -q worldToNDC <<< \"\$1\"" _ "$OUTPUT"

expect 0 "--format exr writes scene-referred frames" -- "$PHOTOPIC" scene orbit -o "$S/exr" --frames 1 \
    --size 96x54 --format exr --set debug.view=exposure
check "an EXR frame" test -s "$S/exr/frame_0000.exr"

expect 0 "the calibration line of the checklist" -- "$PHOTOPIC" scene orbit -o "$S/raw" --frames 2 --size 96x54 \
    --set orbit.post='"raw"' --set orbit.exp=0.9 --set orbit.sun=3.8 --set orbit.amb=0 --set orbit.hemi=0
expect 0 "debug luma" -- "$PHOTOPIC" scene orbit -o "$S/luma" --frames 1 --size 96x54 --set debug.view=luma
for aa in smaa ssaa; do
    expect 0 "aa.mode=$aa" -- "$PHOTOPIC" scene orbit -o "$S/$aa" --frames 2 --size 96x54 --set aa.mode=$aa \
        --set aa.level=1
    check "$aa: no degradation warning" bash -c "! grep -qi 'warn\|no anti-aliasing\|skipped' <<< \"\$1\"" _ "$OUTPUT"
done
expect 2 "an unknown orbit key is refused" -- "$PHOTOPIC" scene orbit -o "$S/bad" --frames 1 --size 32x18 \
    --set orbit.nope=1
check "the key is named" contains "orbit.nope"
expect 2 "a value out of range is refused" -- "$PHOTOPIC" scene orbit -o "$S/bad" --frames 1 --size 32x18 \
    --set orbit.ibl=-1
check "the key is named" contains "orbit.ibl"

expect 0 "--model loads 2CylinderEngine.glb" -- "$PHOTOPIC" scene orbit -o "$S/engine" --frames 2 --size 96x54 \
    --model "$DATA/gltf/2CylinderEngine.glb"
check "frames written" test -s "$S/engine/frame_0001.png"
expect 0 "--model loads a .gltf with a texture beside it" -- "$PHOTOPIC" scene orbit -o "$S/box" --frames 1 \
    --size 96x54 --model "$DATA/gltf/BoxTextured/BoxTextured.gltf"
for f in BoxWithInfinites.glb:"not finite" IndexOutOfRange.gltf:"index 255 past" MissingBin.gltf:"not found" \
    RecursiveNodes.gltf:"its own ancestor" wrongTypes/badArray.gltf:"expected a non-empty array" \
    wrongTypes/badNumber.gltf:"expected a number"; do
    file="${f%%:*}"
    problem="${f#*:}"
    expect 2 "--model $file is refused" -- "$PHOTOPIC" scene orbit -o "$S/bad-model" --frames 1 --size 32x18 \
        --model "$BAD/$file"
    check "$file: the file is named, by its path" contains "\"$BAD/$file\":"
    check "$file: the problem is named" contains "$problem"
    check "$file: nothing written" test ! -e "$S/bad-model"
done
expect 2 "an image given as the model is refused" -- "$PHOTOPIC" scene orbit -o "$S/img-model" --frames 1 \
    --size 32x18 --model "$DATA/Desk.hdr"
check "says it is not a glTF model" contains "\"$DATA/Desk.hdr\": not a glTF 2.0 model"
expect 2 "--model on another scene is refused" -- "$PHOTOPIC" scene testbed -o "$S/tb" --frames 1 --size 32x18 \
    --model "$DATA/gltf/2CylinderEngine.glb"
check "says whose option it is" contains "--model is an option of the orbit scene"

expect 0 "--env with a missing file falls back to the procedural sky" -- "$PHOTOPIC" scene orbit -o "$S/env" \
    --frames 2 --size 64x36 --env "$S/missing.exr"
check "one warning names the file" test "$(grep -c 'missing.exr' <<< "$OUTPUT")" -eq 1
expect 0 "--env with an HDR image" -- "$PHOTOPIC" scene orbit -o "$S/env2" --frames 1 --size 64x36 \
    --env "$DATA/Desk.hdr"

expect 0 "demo --scene orbit (short)" -- "$PHOTOPIC" demo --scene orbit -o "$S/demo" --size 96x54 --seconds 1 \
    --no-video
check "contact sheet written" test -s "$S/demo/contact_sheet.png"
check "exposure plot written" test -s "$S/demo/exposure_plot.png"
check "telemetry written" test -s "$S/demo/telemetry.csv"
finish

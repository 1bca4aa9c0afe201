#!/usr/bin/env bash
# photopic image with 3D EXR input: depth, normals, motion and the camera attributes, --info, --write-aux,
# --camera, and the errors for malformed files (exit 2, the file named).
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
FIXTURE="${PHOTOPIC_EXR3D_FIXTURE:?the test sets PHOTOPIC_EXR3D_FIXTURE to the fixture program}"

expect 0 "fixture writes a 3D EXR sequence" -- "$FIXTURE" write "$S"

expect 0 "--info on a 3D EXR, no output needed" -- "$PHOTOPIC" image --info "$S/seq/frame_0003.exr"
check "--info names the preset and layer" contains "channels: the photopic preset (the file's), layer (unprefixed)"
check "--info lists Z as depth" contains "Z -> depth (linear view depth, planar)"
check "--info lists the normals" contains "N.Z -> normals (world space"
check "--info lists the motion" contains "motion.X -> motion (pixels, current minus previous, y down, unjittered"
check "--info lists the unused channels" contains "unused channels: none"
check "--info lists colour" contains "R -> colour"
check "--info: worldToCamera feeds the view" contains "worldToCamera (m44f) -> camera view"
check "--info: worldToNDC feeds the projection" contains "worldToNDC (m44f) -> camera projection"
check "--info: lens attributes" contains "pinholeFocalLength (float) -> lens focal length"
check "--info: aperture" contains "aperture (float) -> lens f-number"
check "--info: jitter" contains "jitter (v2f) -> sample jitter"
check "--info: the camera it derives" contains "camera (file attributes): near 0.1, far 100"
check "--info: unused attributes say so" contains "screenWindowWidth (float) -> not used"

expect 0 "a 3D EXR sequence renders" -- "$PHOTOPIC" image "$S"/seq/*.exr -o "$S/out" --write-aux "$S/aux"
check "one PNG per frame" test "$(ls "$S/out"/*.png | wc -l)" -eq 10
check "one aux EXR per frame" test "$(ls "$S/aux"/*.aux.exr | wc -l)" -eq 10
expect 0 "aux depth, view-space normals and UV motion hold the expected values" -- "$FIXTURE" check-aux "$S/aux"
# Motion is the surfaces' own unless the mapping says it was measured between the jittered samples.
expect 0 "motion between jittered samples, said so" -- "$PHOTOPIC" image "$S"/seq-jittered-motion/*.exr \
    -o "$S/outj" --write-aux "$S/auxj" --aov motion=:jittered
expect 0 "the jitter is taken out of it" -- "$FIXTURE" check-aux "$S/auxj"
expect 0 "--info says so" -- "$PHOTOPIC" image --info "$S/seq-jittered-motion/frame_0002.exr" --aov motion=:jittered
check "--info: jittered motion" contains "between jittered samples; turned into UV, y up, current minus previous, jitter removed"
expect 2 "an --aov convention a kind does not take" -- "$PHOTOPIC" image "$S/seq/frame_0001.exr" -o "$S/x.png" \
    --aov depth=Z:jittered
check "the error names the word and lists the kind's" contains '"jittered" is no convention of depth (conventions: planar, radial)'
expect 2 "an --aov channel the file lacks" -- "$PHOTOPIC" image "$S/seq/frame_0001.exr" -o "$S/x.png" \
    --aov depth=P.Z
check "the error names the channel and lists the file's" contains "the file has no channel P.Z"
check "no output for a bad mapping" test ! -e "$S/x.png"

# Layers that no pass reads (the default settings read none) are left out (decoded for the first frame only,
# never uploaded), and the images are the same as the run above, which kept every layer for --write-aux;
# with TAA, which reads the motion and the depth, only the normals are left out.
expect 0 "the sequence without --write-aux" -- "$PHOTOPIC" image "$S"/seq/*.exr -o "$S/lean" -v
check "the layers no pass reads are left out" contains "no pass reads the input's depth, normals, motion: left out"
check "the same images as with every layer" diff -r "$S/out" "$S/lean"
expect 0 "with TAA, every layer kept" -- "$PHOTOPIC" image "$S"/seq/*.exr -o "$S/taa" --jitter halton \
    --set aa.mode=taa --write-aux "$S/aux-taa"
expect 0 "with TAA" -- "$PHOTOPIC" image "$S"/seq/*.exr -o "$S/taa-lean" --jitter halton --set aa.mode=taa -v
check "only the normals are left out" contains "no pass reads the input's normals: left out"
check "the same images with TAA" diff -r "$S/taa" "$S/taa-lean"

expect 0 "normals without a camera are skipped, with a warning" -- "$PHOTOPIC" image "$S/plain/plain.exr" -o "$S/plain.png"
check "the warning says why" contains "normals skipped"
check "the image is still written" test -s "$S/plain.png"
expect 0 "--camera gives a camera to a file without one" -- "$PHOTOPIC" image "$S/plain/plain.exr" -o "$S/plain2.png" --camera "$S/camera.json"
check "no normals warning with --camera" eval '! contains "normals skipped"'
expect 0 "--info with --camera" -- "$PHOTOPIC" image --info "$S/plain/plain.exr" --camera "$S/camera.json"
check "--info names the camera's source" contains "camera (--camera): near 0.1, far 100, vertical fov 50"

expect 2 "a normal layer without N.Z" -- "$PHOTOPIC" image "$S/bad/missing_nz.exr" -o "$S/bad.png"
check "the error names the file" contains "missing_nz.exr"
check "the error names the missing channel" contains "but not N.Z"
expect 2 "--info on the same file" -- "$PHOTOPIC" image --info "$S/bad/missing_nz.exr"
check "--info names the file" contains "missing_nz.exr"
expect 2 "a non-finite worldToNDC" -- "$PHOTOPIC" image "$S/bad/nan_ndc.exr" -o "$S/bad.png"
check "the error names the file" contains "nan_ndc.exr"
check "the error names the attribute" contains "worldToNDC has a non-finite entry"
expect 2 "a camera JSON with a bad value" -- "$PHOTOPIC" image "$S/plain/plain.exr" -o "$S/bad.png" --camera "$S/bad/camera.json"
check "the error names the file" contains "bad/camera.json"
check "the error names the key" contains '"verticalFovDeg"'
expect 2 "a camera JSON with an unknown key" -- "$PHOTOPIC" image "$S/plain/plain.exr" -o "$S/bad.png" --camera "$S/bad/camera_key.json"
check "the error names the key" contains '"fov": unknown key'
check "no output for bad inputs" test ! -e "$S/bad.png"

expect 0 "the testbed writes its inputs as EXR" -- "$PHOTOPIC" scene testbed --frames 1 --size 32x18 \
    --format exr -o "$S/testbed"
expect 0 "--info on the testbed's EXR" -- "$PHOTOPIC" image --info "$S/testbed/scene_0000.exr"
check "--info: the testbed's sun direction is written and read" contains "sunDirection (v3f) -> sun direction"

finish

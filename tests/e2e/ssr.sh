#!/usr/bin/env bash
# Screen-space reflections as the CLI shows them: the `ssr` debug view written to EXR holds the raw reflected
# radiance and confidence, and on the testbed's metals it matches the ray tracer's `--truth reflection`. The
# view as PNG, SSR on a 3D EXR input, and the settings' errors too.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
FIXTURE="${PHOTOPIC_SSR_FIXTURE:?the test sets PHOTOPIC_SSR_FIXTURE to the fixture program}"
STILL=(--set testbed.cameraSpeed=0 --set testbed.objectSpeed=0 --set testbed.cameraStart=0.9
    --set testbed.objectStart=0.9)

# intensity 0: traced and resolved, not added, so the reflected radiance is the local shading the ray tracer
# computes (with SSR added, last frame's image would hold a second bounce the truth has not).
expect 0 "the ssr view to EXR" -- "$PHOTOPIC" scene testbed -o "$S/view" --frames 3 --size 160x90 \
    --format exr --set ssr.enabled=true --set ssr.intensity=0 --set debug.view=ssr "${STILL[@]}"
check "frames written" test -s "$S/view/frame_0002.exr"
check "the passes ran, nothing skipped" bash -c "! grep -qi 'skipped' <<< \"\$1\"" _ "$OUTPUT"
expect 0 "reflection truth" -- "$PHOTOPIC" scene testbed --truth reflection -o "$S/truth" --frames 1 \
    --size 160x90 "${STILL[@]}"
expect 0 "object id truth" -- "$PHOTOPIC" scene testbed --truth objectid -o "$S/ids" --frames 1 \
    --size 160x90 "${STILL[@]}"
expect 0 "figures" -- "$FIXTURE" "$S/view/frame_0002.exr" "$S/truth/truth_reflection_0000.exr" \
    "$S/ids/truth_objectid_0000.exr"
echo "$OUTPUT" | sed 's/^/    /'
field() { sed -n "s/.*\b$1=\([^ ]*\).*/\1/p" <<< "$OUTPUT" | head -1; }
check "raw values: finite, confidence in [0, 1]" contains "range=ok"
check "strip pixels exist" awk -v n="$(field metal)" 'BEGIN { exit !(n > 1000) }'
check "most metal pixels get a reflection" awk -v c="$(field covered)" -v n="$(field metal)" \
    'BEGIN { exit !(c >= 0.5 * n) }'
# Edge pixels are not left out here (the GL test does that): measured 86.7% within 10% (160x90, 0.9 s).
check "reflected colour within 10% of the truth on most covered pixels" awk -v w="$(field within10)" \
    'BEGIN { exit !(w >= 0.8) }'

# An EXR frame with Z, N and a camera (the testbed's scene EXR) through `photopic image`: no material, so every
# surface is a dielectric mirror; the view's reflections still match on the metal.
expect 0 "ssr on a 3D EXR input" -- "$PHOTOPIC" image "$S/view/scene_0002.exr" -o "$S/image.exr" \
    --set ssr.enabled=true --set ssr.intensity=0 --set debug.view=ssr
check "the passes ran, nothing skipped" bash -c "! grep -qi 'skipped' <<< \"\$1\"" _ "$OUTPUT"
expect 0 "figures (EXR input)" -- "$FIXTURE" "$S/image.exr" "$S/truth/truth_reflection_0000.exr" \
    "$S/ids/truth_objectid_0000.exr"
echo "$OUTPUT" | sed 's/^/    /'
check "raw values (EXR input)" contains "range=ok"
check "most metal pixels get a reflection (EXR input)" awk -v c="$(field covered)" -v n="$(field metal)" \
    'BEGIN { exit !(c >= 0.5 * n) }'

expect 0 "the view as PNG" -- "$PHOTOPIC" scene testbed -o "$S/png" --frames 2 --size 96x54 \
    --set ssr.enabled=true --set debug.view=ssr "${STILL[@]}"
check "PNG written" test -s "$S/png/frame_0001.png"
expect 0 "a frame with reflections added (intensity 1)" -- "$PHOTOPIC" scene testbed -o "$S/on" --frames 2 \
    --size 96x54 --format exr --set ssr.enabled=true "${STILL[@]}"
check "frame written" test -s "$S/on/frame_0001.exr"

expect 2 "maxSteps out of range names the key" -- "$PHOTOPIC" scene testbed -o "$S/bad" --frames 1 \
    --size 32x18 --set ssr.maxSteps=-1
check "the key is named" contains "ssr.maxSteps"
expect 2 "an unknown resolution names the key" -- "$PHOTOPIC" scene testbed -o "$S/bad2" --frames 1 \
    --size 32x18 --set ssr.resolution=quarter
check "the key is named" contains "ssr.resolution"

finish

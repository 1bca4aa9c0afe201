#!/usr/bin/env bash
# Volumetric light as the CLI shows it: the testbed looking up at the sun through the poles renders with it,
# the `volumetric-light` debug view written to EXR holds the raw light added, brightest at the sun and falling
# in bands away from it; with the sun off screen it is exactly 0; `photopic image` applies it to the scene's
# EXR (depth, camera and its sunDirection attribute); the bench lists the pass's dispatches, the screen mode's
# and (with the bench's synthetic sun shadow map, mode auto) the shadow-map mode's; the settings' errors too.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
lacks() { ! contains "$1"; }
FIXTURE="${PHOTOPIC_VOLUMETRIC_LIGHT_FIXTURE:?the test sets PHOTOPIC_VOLUMETRIC_LIGHT_FIXTURE to the fixture program}"
# Still frames of the second shot (path time 1.5 s: a low camera looking up at the sun through the poles), so
# the accumulation settles over the frames rendered.
SUN=(--set testbed.cameraSpeed=0 --set testbed.objectSpeed=0 --set testbed.cameraStart=1.5
    --set testbed.objectStart=1.5)
# The first shot (0.3 s) looks at the wall with the sun above the image.
AWAY=(--set testbed.cameraSpeed=0 --set testbed.objectSpeed=0 --set testbed.cameraStart=0.3
    --set testbed.objectStart=0.3)
ON=(--set volumetricLight.enabled=true)

expect 0 "the volumetric-light view to EXR" -- "$PHOTOPIC" scene testbed -o "$S/view" --frames 8 --size 160x90 \
    --format exr "${ON[@]}" --set debug.view=volumetric-light "${SUN[@]}"
check "frames written" test -s "$S/view/frame_0007.exr"
check "the pass ran, nothing skipped" bash -c "! grep -qi 'skipped' <<< \"\$1\"" _ "$OUTPUT"
expect 0 "figures by band" -- "$FIXTURE" "$S/view/frame_0007.exr" "$S/view/scene_0007.exr"
echo "$OUTPUT" | sed 's/^/    /'
field() { sed -n "s/.*\b$1=\([^ ]*\).*/\1/p" <<< "$OUTPUT" | head -1; }
check "raw values, finite and not negative" contains "range=ok"
check "the sun is on screen" bash -c "! grep -q 'sun=none' <<< \"\$1\"" _ "$OUTPUT"
check "brightest within 6 px of the sun" awk -v d="$(field peakdist)" 'BEGIN { exit !(d <= 6) }'
check "raw light, not a display value: the peak is above 1" awk -v m="$(field max)" 'BEGIN { exit !(m > 1) }'
check "bands fall away from the sun" awk -v a="$(field ring1)" -v b="$(field ring2)" -v c="$(field ring3)" \
    'BEGIN { exit !(a > 1.5 * b && b > 1.5 * c && c > 0) }'

expect 0 "the view with the sun above the image" -- "$PHOTOPIC" scene testbed -o "$S/away" --frames 2 \
    --size 160x90 --format exr "${ON[@]}" --set debug.view=volumetric-light "${AWAY[@]}"
expect 0 "figures (sun off screen)" -- "$FIXTURE" "$S/away/frame_0001.exr" "$S/away/scene_0001.exr"
echo "$OUTPUT" | sed 's/^/    /'
check "no sun in the image" contains "sun=none"
check "no light added with the sun off screen" awk -v m="$(field max)" 'BEGIN { exit !(m == 0) }'

# One frame of `photopic image` on the scene's EXR: one march, no accumulation, the same bands.
expect 0 "volumetric light on a 3D EXR input" -- "$PHOTOPIC" image "$S/view/scene_0007.exr" -o "$S/image.exr" \
    "${ON[@]}" --set debug.view=volumetric-light
check "the pass ran, nothing skipped" bash -c "! grep -qi 'skipped' <<< \"\$1\"" _ "$OUTPUT"
expect 0 "figures (EXR input)" -- "$FIXTURE" "$S/image.exr" "$S/view/scene_0007.exr"
echo "$OUTPUT" | sed 's/^/    /'
check "raw values (EXR input)" contains "range=ok"
check "bands fall away from the sun (EXR input)" awk -v a="$(field ring1)" -v b="$(field ring2)" \
    -v c="$(field ring3)" 'BEGIN { exit !(a > 1.5 * b && b > 1.5 * c && c > 0) }'
expect 0 "the image with the light added, as PNG" -- "$PHOTOPIC" image "$S/view/scene_0007.exr" \
    -o "$S/image.png" "${ON[@]}"
check "PNG written" test -s "$S/image.png"

expect 0 "an image without depth, camera or sun: the pass is skipped and says so" -- "$PHOTOPIC" image \
    "$DATA/Desk.exr" -o "$S/desk.png" "${ON[@]}"
check "reports what is missing" contains "pass 'volumetric light' skipped: the frame has no camera, sunDirection"
expect 0 "the testbed with volumetric light" -- "$PHOTOPIC" scene testbed -o "$S/png" --frames 2 --size 96x54 \
    "${ON[@]}" "${SUN[@]}"
check "PNG written" test -s "$S/png/frame_0001.png"
expect 0 "bench with volumetric light (screen mode)" -- "$PHOTOPIC" bench --size 64x36 --frames 2 "${ON[@]}" \
    --set volumetricLight.mode=screen
for pass in "volumetric light source" "volumetric light march" "volumetric light resolve" \
    "volumetric light composite"; do
    check "bench lists '$pass'" contains "$pass"
done
check "no shadow-map dispatch in screen mode" lacks "(shadow map)"
# The bench hands over a synthetic sun shadow map, so mode auto (the default) marches it.
expect 0 "bench with volumetric light (auto: the shadow map)" -- "$PHOTOPIC" bench --size 64x36 --frames 2 \
    "${ON[@]}"
for pass in "volumetric light march (shadow map)" "volumetric light resolve (shadow map)" \
    "volumetric light composite (shadow map)"; do
    check "bench lists '$pass'" contains "$pass"
done
check "no screen-mode source with a shadow map" lacks "volumetric light source"
expect 2 "a mode out of the list names the key" -- "$PHOTOPIC" scene testbed -o "$S/bad3" --frames 1 \
    --size 32x18 --set volumetricLight.mode=raymarch
check "the key is named" contains "volumetricLight.mode"

expect 2 "a decay out of range names the key" -- "$PHOTOPIC" scene testbed -o "$S/bad" --frames 1 \
    --size 32x18 --set volumetricLight.decay=1.5
check "the key is named" contains "volumetricLight.decay"
expect 2 "an unknown key is named" -- "$PHOTOPIC" scene testbed -o "$S/bad2" --frames 1 --size 32x18 \
    --set volumetricLight.numSamples=64
check "the key is named" contains "volumetricLight.numSamples"

finish

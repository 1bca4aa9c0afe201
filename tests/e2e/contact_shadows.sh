#!/usr/bin/env bash
# Contact shadows through the testbed's lighting stage, as the CLI shows them: the `contact-shadows` debug
# view written to EXR holds the raw sun visibility, and it matches the ray tracer's `--truth sun` within the
# contact distance (0.18 m, the default): open ground stays at 1, contact-shadowed pixels go dark, surfaces
# turned away from the sun are 0. The `contact-shadows-steps` view and the settings' errors too.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
FIXTURE="${PHOTOPIC_CONTACT_SHADOWS_FIXTURE:?the test sets PHOTOPIC_CONTACT_SHADOWS_FIXTURE to the fixture program}"
# A still frame after the dolly (path time 0.9 s), so the accumulation settles over the frames rendered.
STILL=(--set testbed.cameraSpeed=0 --set testbed.objectSpeed=0 --set testbed.cameraStart=0.9
    --set testbed.objectStart=0.9)

expect 0 "the contact-shadows view to EXR" -- "$PHOTOPIC" scene testbed -o "$S/view" --frames 8 --size 160x90 \
    --format exr --set contactShadows.enabled=true --set debug.view=contact-shadows "${STILL[@]}"
check "frames written" test -s "$S/view/frame_0007.exr"
check "the pass ran, nothing skipped" bash -c "! grep -qi 'skipped' <<< \"\$1\"" _ "$OUTPUT"
expect 0 "sun truth within the contact distance" -- "$PHOTOPIC" scene testbed --truth sun -o "$S/contact" \
    --frames 1 --size 160x90 --set testbed.sunMaxDistance=0.18 "${STILL[@]}"
expect 0 "sun truth within 0.1 mm (0 only where a surface faces away)" -- "$PHOTOPIC" scene testbed \
    --truth sun -o "$S/facing" --frames 1 --size 160x90 --set testbed.sunMaxDistance=0.0001 "${STILL[@]}"
expect 0 "figures by region" -- "$FIXTURE" "$S/view/frame_0007.exr" "$S/contact/truth_sun_0000.exr" \
    "$S/facing/truth_sun_0000.exr"
echo "$OUTPUT" | sed 's/^/    /'
field() { awk -v r="$1" -v k="$2" '$1 == r { for (i = 2; i <= NF; ++i) { split($i, kv, "="); if (kv[1] == k) print kv[2] } }' <<< "$OUTPUT"; }
check "raw values, all in [0, 1]" contains "range=ok"
check "open region (reference 1) stays lit: mean >= 0.99" awk -v m="$(field open mean)" 'BEGIN { exit !(m >= 0.99) }'
check "open region is most of the image" awk -v n="$(field open pixels)" 'BEGIN { exit !(n > 5000) }'
check "contact-shadowed region goes dark: mean <= 0.75" awk -v m="$(field contact mean)" 'BEGIN { exit !(m <= 0.75) }'
check "contact-shadowed region exists" awk -v n="$(field contact pixels)" 'BEGIN { exit !(n > 50) }'
check "surfaces facing away from the sun: 0" awk -v m="$(field away mean)" 'BEGIN { exit !(m <= 0.001) }'

expect 0 "the contact-shadows-steps view to EXR" -- "$PHOTOPIC" scene testbed -o "$S/steps" --frames 2 \
    --size 96x54 --format exr --set contactShadows.enabled=true --set debug.view=contact-shadows-steps "${STILL[@]}"
check "steps frame written" test -s "$S/steps/frame_0001.exr"

expect 0 "the view as PNG" -- "$PHOTOPIC" scene testbed -o "$S/png" --frames 2 --size 96x54 \
    --set contactShadows.enabled=true --set debug.view=contact-shadows "${STILL[@]}"
check "PNG written" test -s "$S/png/frame_0001.png"
expect 2 "without the lighting stage (an image), the view cannot be made: an error, not a plain image" -- \
    "$PHOTOPIC" image "$S/view/scene_0000.exr" -o "$S/img.png" --set contactShadows.enabled=true \
    --set debug.view=contact-shadows
check "says once why contact shadows cannot run" contains "cannot apply them"
check "names the view and what it lacks" contains "--debug contact-shadows"
check "no image written" test ! -e "$S/img.png"

expect 2 "a thickness out of range names the key" -- "$PHOTOPIC" scene testbed -o "$S/bad" --frames 1 \
    --size 32x18 --set contactShadows.thickness=-1
check "the key is named" contains "contactShadows.thickness"
expect 2 "a mask that is not a list of ids" -- "$PHOTOPIC" scene testbed -o "$S/bad2" --frames 1 --size 32x18 \
    --set 'contactShadows.mask=[0]'
check "the element is named" contains "contactShadows.mask[0]"

finish

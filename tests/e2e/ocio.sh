#!/usr/bin/env bash
# OpenColorIO display output: with tests/data/ocio/srgb.ocio (scene_linear linear Rec.709, display sRGB, view
# Standard = the sRGB OETF) the display PNG is the sRGB encoding of the scene-referred image that an .exr output
# holds; the config comes from --ocio-config or $OCIO; bad names, a missing config and a config without a
# scene_linear role fail with exit 2, name the value and write nothing.
source "$(dirname "$0")/lib.bash"
FIXTURE="${PHOTOPIC_OCIO_FIXTURE:?the test sets PHOTOPIC_OCIO_FIXTURE to the fixture program}"
CONFIGS="$(cd "$(dirname "$0")/../data/ocio" && pwd)"
cd "$SCRATCH"
IN="$DATA/blender_sunrise.exr"

figure() { sed -n "s/.*\b$1=\([^ ]*\).*/\1/p" <<<"$OUTPUT"; }
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }
differ() { ! cmp -s "$1" "$2"; }

expect 0 "scene-referred EXR" -- "$PHOTOPIC" image "$IN" -o scene.exr
expect 0 "OCIO sRGB / Standard" -- "$PHOTOPIC" image "$IN" -o ocio.png --ocio-config "$CONFIGS/srgb.ocio" \
    --ocio-display sRGB --ocio-view Standard
check "the log names the display and view" contains "display 'sRGB', view 'Standard'"
expect 0 "compare with the sRGB encoding" -- "$FIXTURE" scene.exr ocio.png
echo "    $OUTPUT"
# The PNG is rounded to whole code values (0.5 at most, 0.25 on average) from full floats, the reference is
# computed from the EXR's half floats (a few hundredths of a code value more).
check "within 0.6 code values of the sRGB encoding ($(figure maxdiff))" below "$(figure maxdiff)" 0.6
check "mean difference under 0.3 code values ($(figure meandiff))" below "$(figure meandiff)" 0.3
expect 0 "Photopic's own tone curve" -- "$PHOTOPIC" image "$IN" -o own.png
check "OCIO replaces the tone curve (the images differ)" differ own.png ocio.png
expect 0 "OCIO at 16 bits" -- "$PHOTOPIC" image "$IN" -o ocio16.png --bit-depth 16 \
    --ocio-config "$CONFIGS/srgb.ocio" --ocio-display sRGB --ocio-view Standard
check "a 16-bit PNG (IHDR bit depth)" [ "$(od -An -tu1 -j24 -N1 ocio16.png | tr -d ' ')" = 16 ]
expect 0 "OCIO into a TIFF" -- "$PHOTOPIC" image "$IN" -o ocio.tif --ocio-config "$CONFIGS/srgb.ocio"
check "a TIFF (little-endian magic)" [ "$(od -An -tx1 -N4 ocio.tif | tr -d ' ')" = 49492a00 ]

expect 0 "config from \$OCIO, default view" -- env OCIO="$CONFIGS/srgb.ocio" "$PHOTOPIC" image "$IN" \
    -o env.png --ocio-display sRGB
check "\$OCIO and the default view (Standard) give the same image" cmp -s env.png ocio.png
expect 0 "--ocio-config wins over \$OCIO" -- env OCIO=/nonexistent.ocio "$PHOTOPIC" image "$IN" \
    -o cfg.png --ocio-config "$CONFIGS/srgb.ocio" --ocio-view Standard
check "... same image" cmp -s cfg.png ocio.png

expect 2 "unknown display" -- "$PHOTOPIC" image "$IN" -o bad1.png --ocio-config "$CONFIGS/srgb.ocio" \
    --ocio-display Rec2020
check "names it and lists the displays" contains "no display 'Rec2020' (displays: 'sRGB')"
expect 2 "unknown view" -- "$PHOTOPIC" image "$IN" -o bad2.png --ocio-config "$CONFIGS/srgb.ocio" \
    --ocio-display sRGB --ocio-view Filmic
check "names it and lists the views" contains "no view 'Filmic' (views: 'Standard', 'Raw')"
expect 2 "missing config" -- "$PHOTOPIC" image "$IN" -o bad3.png --ocio-config missing.ocio --ocio-display sRGB
check "names the file" contains "missing.ocio does not exist"
expect 2 "no config at all" -- env -u OCIO "$PHOTOPIC" image "$IN" -o bad4.png --ocio-display sRGB
check "says how to give one" contains "give --ocio-config FILE or set the OCIO environment variable"
expect 2 "config without scene_linear" -- "$PHOTOPIC" image "$IN" -o bad5.png \
    --ocio-config "$CONFIGS/no-scene-linear.ocio"
check "says the role is missing and lists the roles" contains "has no 'scene_linear' role"
check "... lists the roles it has" contains "(roles: 'default')"
echo "not: [ yaml" >broken.ocio
expect 2 "unparsable config" -- "$PHOTOPIC" image "$IN" -o bad6.png --ocio-config broken.ocio
check "names the file" contains "broken.ocio cannot be used"
expect 2 "EXR output with OCIO" -- "$PHOTOPIC" image "$IN" -o bad7.exr --ocio-config "$CONFIGS/srgb.ocio"
check "says OCIO makes the display image" contains "make the display image (PNG, TIFF, JPEG)"
check "no output from a failed run" bash -c '! ls bad*.png bad*.exr 2>/dev/null | grep -q .'
finish

#!/usr/bin/env bash
# SMAA from the CLI: aa.mode=smaa changes the image (and only through the anti-aliasing), each quality preset
# runs, smaa.subpixel 0 (the reference SMAA 1x) differs from the default, and a quality name that is not one
# of them or a subpixel amount outside 0..1 is a usage error that names the key.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"

expect 0 "no anti-aliasing" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/none.png" --set aa.mode=none
check "no-AA image written" test -s "$S/none.png"
expect 0 "aa.mode=smaa" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/smaa.png" --set aa.mode=smaa
check "SMAA image written" test -s "$S/smaa.png"
check "SMAA changes the image" bash -c '! cmp -s "$0" "$1"' "$S/none.png" "$S/smaa.png"

for quality in low medium high ultra; do
    expect 0 "smaa.quality=$quality" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/smaa-$quality.png" \
        --set aa.mode=smaa --set smaa.quality=$quality
    check "$quality image written" test -s "$S/smaa-$quality.png"
done
check "high is the default quality" cmp -s "$S/smaa.png" "$S/smaa-high.png"
check "ultra differs from low" bash -c '! cmp -s "$0" "$1"' "$S/smaa-low.png" "$S/smaa-ultra.png"

expect 0 "smaa.subpixel=0" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/smaa-reference.png" \
    --set aa.mode=smaa --set smaa.subpixel=0
check "the ridge step changes the image" bash -c '! cmp -s "$0" "$1"' "$S/smaa.png" "$S/smaa-reference.png"
expect 2 "subpixel out of range" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/bad-subpixel.png" \
    --set aa.mode=smaa --set smaa.subpixel=1.5
check "error names the subpixel key" contains "smaa.subpixel"
check "no output for a bad subpixel" test ! -e "$S/bad-subpixel.png"

expect 2 "unknown SMAA quality" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/bad.png" --set aa.mode=smaa \
    --set smaa.quality=extreme
check "error names the key" contains "smaa.quality"
check "allowed qualities listed" contains "ultra"
check "no output for a bad quality" test ! -e "$S/bad.png"

finish

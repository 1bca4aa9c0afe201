#!/usr/bin/env bash
# Golden outputs: the demo, GoldenGate with auto exposure + FXAA + grain, the canvas scene, debug views, the
# legacy tier and an EXR output are byte-identical to what the 2D chain rendered before the pass graph
# rewrite (golden.sha256). PNG bytes depend on libpng and zlib: the hashes are Debian 12's. The images run
# with --preset realtime, the look they were rendered with before `photopic image` defaulted to stills: they
# hold the chain's bytes, not a look.
source "$(dirname "$0")/lib.bash"
cd "$SCRATCH"
expect 0 "demo" -- "$PHOTOPIC" demo -o demo
expect 0 "GoldenGate, AE + FXAA + grain" -- "$PHOTOPIC" image "$DATA/GoldenGate.exr" -o gg.png \
    --preset realtime --set autoExposure.enabled=true --set fxaa.enabled=true --set grain.enabled=true
expect 0 "Desk, histogram overlay" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o desk_hist.png \
    --preset realtime --debug histogram --set autoExposure.enabled=true --set autoExposure.metering=histogram
expect 0 "sunrise, flare + vignette + dazzle + grading" -- "$PHOTOPIC" image "$DATA/blender_sunrise.exr" \
    -o sun.png --preset realtime --set lensFlare.enabled=true --set vignette.enabled=true \
    --set dazzle.enabled=true --set colorGrading.enabled=true
expect 0 "Desk, ev view" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o desk_ev.png --preset realtime --debug ev
expect 0 "Desk, legacy tier" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o desk_legacy.png \
    --preset realtime --set quality=legacy
expect 0 "Desk, scene-referred EXR" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o desk.exr --preset realtime
expect 0 "canvas scene" -- "$PHOTOPIC" scene canvas -o canvas --frames 10 --size 192x108
while read -r hash file; do
    [[ "$hash" == \#* || -z "$hash" ]] && continue
    check "$file is byte-identical" [ "$(sha256sum "$file" 2>/dev/null | cut -d' ' -f1)" = "$hash" ]
done < "$(dirname "$0")/golden.sha256"
finish

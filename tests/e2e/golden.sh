#!/usr/bin/env bash
# Golden outputs: the demo, GoldenGate with auto exposure + FXAA + grain, the canvas scene, debug views, the
# legacy tier and an EXR output are identical to what the 2D chain rendered before the pass graph rewrite
# (golden.sha256): a PNG's pixels, size and colour type, an EXR's and a CSV's bytes (EXR bytes depend on
# OpenEXR and zlib: the hashes are Debian 12's). The images run
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
# A PNG's hash is that of its image rather than of its bytes: the SHA-256 of the IHDR chunk's data followed by the
# inflated IDAT stream (every row with its filter type byte; the writer filters no row), so changing the deflate
# encoder changes no hash while any changed pixel, size or colour type does. Other files: their bytes.
content_hash() {
    case "$1" in
    *.png)
        python3 - "$1" 2>/dev/null <<'PY'
import hashlib, struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n"
at, header, idat = 8, b"", []
while at < len(data):
    (n,) = struct.unpack(">I", data[at:at + 4])
    kind, body = data[at + 4:at + 8], data[at + 8:at + 8 + n]
    assert struct.unpack(">I", data[at + 8 + n:at + 12 + n])[0] == zlib.crc32(kind + body)
    header = body if kind == b"IHDR" else header
    if kind == b"IDAT":
        idat.append(body)
    at += 12 + n
print(hashlib.sha256(header + zlib.decompress(b"".join(idat))).hexdigest())
PY
        ;;
    *) sha256sum "$1" 2>/dev/null | cut -d' ' -f1 ;;
    esac
}
while read -r hash file; do
    [[ "$hash" == \#* || -z "$hash" ]] && continue
    check "$file is identical" [ "$(content_hash "$file")" = "$hash" ]
done < "$(dirname "$0")/golden.sha256"
finish

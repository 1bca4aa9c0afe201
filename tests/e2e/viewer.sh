#!/usr/bin/env bash
# photopic-view under Xvfb (GLX on Mesa llvmpipe): frames, screenshot of the window (scene + ImGui panels),
# --save, bad input. scripts/deps.sh installs xvfb and xauth.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
VIEW="$(dirname "$PHOTOPIC")/photopic-view"

if [ ! -x "$VIEW" ]; then
    echo "FAIL: $VIEW was not built (needs libglfw3-dev and libimgui-dev; run scripts/deps.sh)"
    exit 1
fi
source "$(dirname "$0")/../../scripts/xvfb.bash"
start_xvfb "$S" || exit 1

# The PNG reader the checks below share (each puts "$S" on its path): an 8-bit RGB or RGBA PNG's size, bytes per
# pixel and unfiltered rows.
cat > "$S/png_rows.py" <<'PY'
import struct, zlib
def read(path):
    data, pos, idat = open(path, "rb").read(), 8, b""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    assert depth == 8, (path, depth)
    bpp = {2: 3, 6: 4}[ctype]
    raw, stride, prev, rows = zlib.decompress(idat), w * bpp, bytearray(w * bpp), []
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            p = a + b - c
            pred = [0, a, b, (a + b) // 2, a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else (b if abs(p - b) <= abs(p - c) else c)][f]
            line[i] = (line[i] + pred) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, bpp, rows
PY

expect 0 "tabletop, 90 frames, screenshot and save" -- "$VIEW" --scene tabletop --frames 90 --size 640x360 \
    --fixed-dt 0.0333 --screenshot "$S/view.png" --save "$S/view.json" --set autoExposure.tauDarken=0.5
check "reports a GL 4.5 (or newer) context" contains "GL 4.5"
check "screenshot written" test -s "$S/view.png"
check "screenshot is 640x360 and not uniform" python3 - "$S/view.png" "$S" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from png_rows import read
w, h, bpp, rows = read(sys.argv[1])
assert (w, h) == (640, 360), (w, h)
stride = w * bpp
colours = {r[i:i + 3] for r in rows[::4] for i in range(0, stride, bpp * 4)}
print(len(colours), "distinct colours")
sys.exit(0 if len(colours) > 64 else 1)
PY
check "saved settings written" test -s "$S/view.json"
expect 0 "saved settings pass photopic settings --check" -- "$PHOTOPIC" settings --check "$S/view.json"
check "saved settings keep the --set value" grep -q '"tauDarken": 0.5' "$S/view.json"

# The key map and F12, through --press (the same path as a key press): each toggle is logged, F12 writes the
# --save file, named in the log, and that file loads back as the same settings.
expect 0 "keys B, X, 0, then F12" -- "$VIEW" --scene testbed --size 160x90 --frames 6 --fixed-dt 0.0333 \
    --press B,X,0,F12 --save "$S/f12.json"
check "B is logged" contains "bloom off (B)"
check "X is logged" contains "auto exposure off (X)"
check "0 is logged" contains "tone curve aces (0)"
check "F12 names the file it wrote" contains "saved $S/f12.json (F12)"
check "the file holds the toggled settings" python3 - "$S/f12.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))["postEffects"]
sys.exit(0 if (p["bloom"]["enabled"], p["autoExposure"]["enabled"], p["tonemapping"]["mode"]) == (False, False, "aces") else 1)
PY
expect 0 "the F12 file passes photopic settings --check" -- "$PHOTOPIC" settings --check "$S/f12.json"
expect 0 "loaded back, F12 writes it again" -- "$VIEW" --scene testbed --size 160x90 --frames 2 --fixed-dt 0.0333 \
    --settings "$S/f12.json" --press F12 --save "$S/f12_again.json"
check "... byte for byte the same settings" cmp -s "$S/f12.json" "$S/f12_again.json"
expect 2 "an unknown --press key exits 2" -- "$VIEW" --frames 1 --press Q
check "names it" contains "'Q' is not a key"

# Orbit camera: a drag and the wheel move the testbed's camera (held still by cameraSpeed=0 so that only the
# input moves it); the same drag on a scene without an interactive camera changes nothing. Compared right of
# the panels (x >= 330), as mean |difference| per channel.
cat > "$S/right_diff.py" <<'PY'
import sys
from png_rows import read
(w, h, b1, r1), (_, _, b2, r2) = read(sys.argv[1]), read(sys.argv[2])
d = [abs(r1[y][x * b1 + c] - r2[y][x * b2 + c]) for y in range(h) for x in range(330, w) for c in range(3)]
mean = sum(d) / len(d)
print("mean |diff| right of the panels", round(mean, 3))
sys.exit(0 if (mean > float(sys.argv[4]) if sys.argv[3] == "more" else mean <= float(sys.argv[4])) else 1)
PY
STILL=(--scene testbed --size 480x200 --frames 3 --fixed-dt 0.0333 --set testbed.cameraSpeed=0)
expect 0 "testbed, no input" -- "$VIEW" "${STILL[@]}" --screenshot "$S/still.png"
expect 0 "testbed, a drag" -- "$VIEW" "${STILL[@]}" --press drag:120:0 --screenshot "$S/dragged.png"
expect 0 "testbed, the wheel" -- "$VIEW" "${STILL[@]}" --press wheel:4 --screenshot "$S/zoomed.png"
check "the drag turns the view (mean |diff| > 4)" python3 "$S/right_diff.py" "$S/still.png" "$S/dragged.png" more 4
check "the wheel zooms the view (mean |diff| > 4)" python3 "$S/right_diff.py" "$S/still.png" "$S/zoomed.png" more 4
GRAD=(--scene gradient --size 480x200 --frames 3 --fixed-dt 0.0333)
expect 0 "gradient, no input" -- "$VIEW" "${GRAD[@]}" --screenshot "$S/g.png"
expect 0 "gradient, a drag" -- "$VIEW" "${GRAD[@]}" --press drag:120:0 --screenshot "$S/g_dragged.png"
check "a scene without an interactive camera ignores it" python3 "$S/right_diff.py" "$S/g.png" "$S/g_dragged.png" less 0
# The orbit scene (its image-based light built at start) under the same drag, at a size where the ship shows
# right of the panels; --help names it with the other scenes.
ORBIT=(--scene orbit --size 640x360 --frames 3 --fixed-dt 0.0333)
expect 0 "orbit, no input" -- "$VIEW" "${ORBIT[@]}" --screenshot "$S/orbit.png"
expect 0 "orbit, a drag" -- "$VIEW" "${ORBIT[@]}" --press drag:120:0 --screenshot "$S/orbit_dragged.png"
check "the drag turns the orbit scene's camera (mean |diff| > 1)" python3 "$S/right_diff.py" "$S/orbit.png" \
    "$S/orbit_dragged.png" more 1
expect 0 "--help" -- "$VIEW" --help
check "--help names every built-in scene" contains "built-in scene: gradient, canvas, tabletop, testbed, orbit"

expect 2 "bad --set exits 2" -- "$VIEW" --frames 1 --set autoExposure.tauDarken=-3
check "names the bad key" contains "tauDarken"
expect 2 "bad scene --set exits 2" -- "$VIEW" --scene tabletop --frames 1 --set tabletop.nosuchkey=1
expect 2 "unknown scene exits 2" -- "$VIEW" --scene nosuch --frames 1
expect 1 "no display exits 1" -- env -u DISPLAY -u WAYLAND_DISPLAY "$VIEW" --frames 1
check "says it needs a display" contains "needs a display"

# An image file through the live pipeline: the window takes the image's size, and where no panel covers it
# the screenshot is the image `photopic image` writes with the same settings (both give files the stills look).
DESK="$(dirname "$0")/../../data/Desk.exr"
expect 0 "views an EXR file" -- "$VIEW" "$DESK" --frames 3 --fixed-dt 0.0333 --screenshot "$S/desk_view.png"
check "names the file and takes its size" contains "Desk.exr at 644x874"
expect 0 "the same file through photopic image" -- "$PHOTOPIC" image "$DESK" -o "$S/desk_cli.png"
check "right of the panels the window shows the pipeline's image (mean |diff| <= 2/255)" python3 - \
    "$S/desk_view.png" "$S/desk_cli.png" "$S" <<'PY'
import sys
sys.path.insert(0, sys.argv[3])
from png_rows import read
(w, h, bv, view), (w2, h2, bc, cli) = read(sys.argv[1]), read(sys.argv[2])
assert (w, h) == (w2, h2) == (644, 874), (w, h, w2, h2)
diffs = [abs(view[y][x * bv + c] - cli[y][x * bc + c]) for y in range(0, h, 2) for x in range(340, w, 2) for c in range(3)]
mean = sum(diffs) / len(diffs)
print("mean |diff|", mean)
sys.exit(0 if mean <= 2.0 else 1)
PY
expect 0 "--preset realtime on a file" -- "$VIEW" "$DESK" --preset realtime --frames 2 --fixed-dt 0.0333 \
    --screenshot "$S/desk_realtime.png"
check "... changes the look (the realtime bloom veils the window)" bash -c "! cmp -s '$S/desk_view.png' '$S/desk_realtime.png'"
expect 2 "an unknown preset exits 2" -- "$VIEW" "$DESK" --preset glossy --frames 1
check "names it and lists the presets" contains "unknown preset 'glossy'"
expect 2 "a missing file exits 2 before any window" -- "$VIEW" "$S/nosuch.exr" --frames 1
check "names the missing file" contains "nosuch.exr"
expect 2 "a file and --scene together exit 2" -- "$VIEW" "$DESK" --scene testbed --frames 1

# A renderer's frames as photopic image reads them: Blender's multilayer EXRs by pattern, the camera track, a
# debug view of their depth (which needs the track's camera).
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
expect 0 "Blender's frames with their camera track" -- "$VIEW" "$ROOT/tests/data/blender/passes/frame_%04d.exr" \
    --camera "$ROOT/tests/data/blender/track.json" --frames 3 --fixed-dt 0.0417 --set dof.enabled=true \
    --set debug.view=depth
check "no skipped pass (the depth view has its camera)" eval '! contains "skipped"'
expect 2 "an --aov the files lack" -- "$VIEW" "$ROOT/tests/data/blender/passes/frame_0003.exr" --aov depth=P.Z \
    --frames 1
check "names the channel" contains "the file has no channel P.Z"

finish

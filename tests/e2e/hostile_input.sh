#!/usr/bin/env bash
# Input that crashed, hung or was misread: values nested or sized to exhaust whatever prints them, files that
# are not files, names that read as options, bytes that would reach the terminal, valid files refused
# (PNGs whose rows compress far), deep EXRs, an EXR whose data window leaves its display window. Each is
# refused with exit 2 and a short message naming it, or accepted, as a user would expect.
source "$(dirname "$0")/lib.bash"
HERE="$(cd "$(dirname "$0")" && pwd)"
IMG="$HERE/../../fuzz/corpus/hdr/flat_3x2.hdr"
CONFIGS="$HERE/../data/ocio"
cd "$SCRATCH"
short() { [ "${#OUTPUT}" -lt 2000 ]; }
no_escape() { ! grep -q $'\e' <<< "$OUTPUT"; }

# --- JSON nested or sized to exhaust the printer
python3 -c 'print("{\"version\": 1, \"postEffects\": {\"bloom\": " + "[" * 70000 + "]" * 70000 + "}}")' > deep.json
expect 2 "settings nested 70,000 deep" -- "$PHOTOPIC" settings --check deep.json
check "says how deep is too deep" contains "nested deeper than 64 levels"
check "names the file" contains "deep.json"
check "a short message" short
expect 2 "--settings nested 70,000 deep" -- "$PHOTOPIC" image "$IMG" -o deep.png --settings deep.json
check "no output" test ! -e deep.png
# (60,000: one command-line argument holds at most 128 KiB.)
expect 2 "--set nested 60,000 deep" -- "$PHOTOPIC" image "$IMG" -o deep.png \
    --set "bloom=$(python3 -c 'print("[" * 60000 + "]" * 60000)')"
check "says how deep is too deep" contains "nested deeper than 64 levels"
check "a short message" short
python3 -c 'print("{\"version\": 1, \"postEffects\": {\"bloom\": [" + ",".join(["0"] * 5000000) + "]}}")' > wide.json
expect 2 "a 10 MB array where an object belongs" -- "$PHOTOPIC" settings --check wide.json
check "says what was expected" contains "expected an object, got array [0,0,0"
check "the value is cut, not copied whole" short
python3 -c 'print("{\"version\": 1, \"postEffects\": {" + ",".join("\"k%d\": 1" % i for i in range(100000)) + "}}")' > keys.json
expect 2 "100,000 unknown keys" -- "$PHOTOPIC" settings --check keys.json
check "the first ones listed, the rest counted" contains "and 99980 more"
check "a short enough message" test "${#OUTPUT}" -lt 20000
expect 2 "--set a key of 50,000 parts" -- "$PHOTOPIC" image "$IMG" -o parts.png \
    --set "$(python3 -c 'print(".".join(["a"] * 50000))')=1"
check "a short message" short

# --- duplicate keys
printf '{"version": 1, "postEffects": {"bloom": {"intensity": 0.5, "intensity": 2}}}' > dup.json
expect 2 "settings with a key twice" -- "$PHOTOPIC" settings --check dup.json
check "names the key and where" contains 'duplicate key "intensity" at /postEffects/bloom'
printf '{"position": [0, 0, 5], "target": [0, 0, 0], "position": [1, 1, 1]}' > dupcam.json
expect 2 "camera with a key twice" -- "$PHOTOPIC" image "$IMG" -o cam.png --camera dupcam.json
check "names the key" contains 'duplicate key "position"'

# --- numbers beyond range, bytes for the terminal
expect 2 "--set x=1e400" -- "$PHOTOPIC" image "$IMG" -o big.png --set bloom.intensity=1e400
check "says the number is out of range" contains "beyond the range of a double"
check "not taken as a string" test "$(grep -c 'got string' <<< "$OUTPUT")" = 0
expect 2 "an ESC byte in --ocio-display" -- "$PHOTOPIC" image "$IMG" -o esc.png \
    --ocio-config "$CONFIGS/srgb.ocio" --ocio-display $'\e[31mred'
check "shown as \\x1b" contains '\x1b[31mred'
check "no raw ESC reaches the terminal" no_escape
expect 2 "an ESC byte in --set" -- "$PHOTOPIC" image "$IMG" -o esc.png --set $'tonemapping.mode=\e[2J'
check "no raw ESC reaches the terminal" no_escape

# --- files that are not files, names that are options
mkfifo cam.fifo
expect 2 "--camera naming a FIFO" -- timeout 20 "$PHOTOPIC" image "$IMG" -o fifo.png --camera cam.fifo
check "says it is not a regular file" contains "not a regular file"
mkfifo settings.fifo
expect 2 "--settings naming a FIFO" -- timeout 20 "$PHOTOPIC" settings --check settings.fifo
check "says it is not a regular file" contains "not a regular file"
expect 2 "-o -y" -- "$PHOTOPIC" image "$IMG" -o -y
check "says it reads as an option" contains "looks like an option"
check "no folder named -y" test ! -e ./-y
expect 0 "-o ./-y is a file of that name" -- "$PHOTOPIC" image "$IMG" -o ./-y.png
check "written" test -s ./-y.png

# --- valid PNGs whose rows compress far (bound from the rows as stored)
python3 - << 'EOF'
import struct, zlib
def png(name, width, height, depth, colour, row, interlace=0):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    raw = b"".join(b"\0" + row for _ in range(height))
    if interlace:  # Adam7 of a flat image: each pass's rows, filter byte 0
        raw = b""
        channels = {0: 1, 2: 3, 4: 2, 6: 4, 3: 1}[colour]
        for x0, y0, dx, dy in [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]:
            w = (width - x0 + dx - 1) // dx if width > x0 else 0
            h = (height - y0 + dy - 1) // dy if height > y0 else 0
            if w and h:
                raw += (b"\0" + row[: (w * channels * depth + 7) // 8]) * h
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, colour, 0, 0, interlace))
    data += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(name, "wb").write(data)
png("black1080.png", 1920, 1080, 8, 2, b"\0" * 1920 * 3)
png("grey1080.png", 1920, 1080, 8, 0, b"\x80" * 1920)
png("white4k_1bit.png", 3840, 2160, 1, 0, b"\xff" * 480)
png("white4k_interlaced.png", 3840, 2160, 8, 0, b"\xff" * 3840, interlace=1)
png("mask16.png", 1024, 1024, 16, 0, b"\xff\xff" * 1024)
EOF
for f in black1080 grey1080 white4k_1bit white4k_interlaced mask16; do
    expect 0 "a flat PNG libpng reads: $f ($(stat -c %s $f.png) bytes)" -- "$PHOTOPIC" image "$f.png" -o "out_$f.png" -q
done
python3 -c 'import struct,zlib,sys; d=b"\x89PNG\r\n\x1a\n"; ih=struct.pack(">IIBBBBB",16384,16384,8,2,0,0,0); d+=struct.pack(">I",13)+b"IHDR"+ih+struct.pack(">I",zlib.crc32(b"IHDR"+ih)); d+=struct.pack(">I",10)+b"IDAT"+bytes(10)+struct.pack(">I",zlib.crc32(b"IDAT"+bytes(10))); d+=struct.pack(">I",0)+b"IEND"+struct.pack(">I",zlib.crc32(b"IEND")); open("liar.png","wb").write(d)'
expect 2 "a PNG whose header claims more than its bytes can hold" -- "$PHOTOPIC" image liar.png -o liar_out.png
check "named, as truncated" contains "cannot hold the 16384x16384 image"

# --- OpenEXR: deep data, a data window outside the display window
python3 - << 'EOF'
import struct
def attr(name, kind, value):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value
def channels(names, kind=1):
    return b"".join(n.encode() + b"\0" + struct.pack("<iB3xii", kind, 0, 1, 1) for n in names) + b"\0"
def box(x0, y0, x1, y1):
    return struct.pack("<4i", x0, y0, x1, y1)
common = (attr("compression", "compression", b"\0") + attr("lineOrder", "lineOrder", b"\0")
          + attr("pixelAspectRatio", "float", struct.pack("<f", 1)) + attr("screenWindowCenter", "v2f", struct.pack("<2f", 0, 0))
          + attr("screenWindowWidth", "float", struct.pack("<f", 1)))
# A flat 4x4 half RGB image whose data window (2,2)-(5,5) lies partly outside its display window (0,0)-(3,3).
header = (attr("channels", "chlist", channels("BGR")) + common + attr("dataWindow", "box2i", box(2, 2, 5, 5))
          + attr("displayWindow", "box2i", box(0, 0, 3, 3)) + b"\0")
start = 8 + len(header) + 8 * 4
line = struct.pack("<H", 0x3C00) * 4 * 3
chunks = b"".join(struct.pack("<ii", y, len(line)) + line for y in range(2, 6))
offsets = b"".join(struct.pack("<Q", start + i * (8 + len(line))) for i in range(4))
open("window.exr", "wb").write(b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + header + offsets + chunks)
# A deep scanline file (version flag 0x800, type deepscanline), cut after its header.
deep = (attr("channels", "chlist", channels(["A", "Z"], 2)) + common + attr("dataWindow", "box2i", box(0, 0, 15, 15))
        + attr("displayWindow", "box2i", box(0, 0, 15, 15)) + attr("type", "string", b"deepscanline")
        + attr("version", "int", struct.pack("<i", 1)) + attr("chunkCount", "int", struct.pack("<i", 16))
        + attr("maxSamplesPerPixel", "int", struct.pack("<i", 4)) + b"\0")
open("deep.exr", "wb").write(b"\x76\x2f\x31\x01" + struct.pack("<i", 2 | 0x800) + deep + b"\0" * 40)
EOF
expect 0 "an EXR whose data window leaves its display window" -- "$PHOTOPIC" image window.exr -o window.png
check "says the whole data window is processed" contains "reaches outside its display window"
check "written at the data window's size" contains "4x4"
expect 2 "a deep EXR" -- "$PHOTOPIC" image deep.exr -o deep_out.png
check "says deep data is not read" contains "deep data is not read"
check "names the file" contains "deep.exr"
expect 2 "--info on a deep EXR" -- "$PHOTOPIC" image deep.exr --info
check "says deep data is not read" contains "deep data is not read"
# --- glTF: a texture that decodes to 16384 x 16384 from 33 KB, as a file and as a data: URI
python3 - << 'EOF'
import base64, json, struct, zlib
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
raw = (b"\0" + b"\0" * 2048) * 16384
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 16384, 16384, 1, 0, 0, 0, 0))
       + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
open("bomb.png", "wb").write(png)
tri = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<6f", 0, 0, 1, 0, 0, 1)
for name, uri in (("bomb_file.gltf", "bomb.png"),
                  ("bomb_data.gltf", "data:image/png;base64," + base64.b64encode(png).decode())):
    json.dump({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
               "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
               "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
               "textures": [{"source": 0}], "images": [{"uri": uri}],
               "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                              "min": [0, 0, 0], "max": [1, 1, 0]},
                             {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}],
               "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
               "buffers": [{"byteLength": 60,
                            "uri": "data:application/octet-stream;base64," + base64.b64encode(tri).decode()}]},
              open(name, "w"))
EOF
for model in bomb_file bomb_data; do
    start=$(date +%s%N)
    expect 2 "a glTF texture bomb ($model)" -- "$PHOTOPIC" scene orbit --model "$model.gltf" --frames 1 \
        --size 64x36 -o "$model"
    check "$model: refused from the header, by the pixel limit" contains "over the limit of 67108864 pixels"
    check "$model: refused before decoding (under 5 s)" test $((($(date +%s%N) - start) / 1000000)) -lt 5000
done
finish

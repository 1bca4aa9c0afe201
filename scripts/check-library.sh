#!/usr/bin/env bash
# The library as users get it: installs the release build into build/install, then builds two hosts against
# the installed package alone and runs them:
#   examples/minimal    <GL/gl.h> with prototypes as its GL access, a headless context, a host texture target;
#   examples/glfw-host  a GLFW window with glad as its loader and its own 3D scene (colour, depth, normals,
#                       motion handed over by name), run on a private Xvfb server for 30 frames, its last frame
#                       checked to be an image (not black, not one colour).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="${JOBS:-$(nproc)}"

cmake --install build/release --prefix build/install > /dev/null
for example in minimal glfw-host; do
    cmake -S "examples/$example" -B "build/example-$example" -DCMAKE_PREFIX_PATH="$PWD/build/install" \
        > "build/example-$example.configure.log" 2>&1 || { cat "build/example-$example.configure.log"; exit 1; }
    cmake --build "build/example-$example" -j"$jobs"
done

build/example-minimal/photopic_minimal

shot=build/example-glfw-host/frame.ppm
rm -f "$shot"
scripts/with-xvfb.sh build/example-glfw-host/photopic_glfw_host --frames 30 --size 320x180 --screenshot "$shot"
python3 - "$shot" <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
magic, size, depth, pixels = data.split(b"\n", 3)
w, h = map(int, size.split())
assert magic == b"P6" and (w, h) == (320, 180) and len(pixels) == w * h * 3, "not a 320x180 PPM"
mean = sum(pixels) / len(pixels)
assert 20 < mean < 245, f"mean {mean:.1f}: the frame is black or blown out"
assert len(set(pixels[i:i + 3] for i in range(0, len(pixels), 3))) > 100, "the frame is nearly one colour"
print(f"photopic_glfw_host: 320x180 frame, mean {mean:.1f}")
PY

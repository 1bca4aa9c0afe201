#!/usr/bin/env bash
# Bad input and bad outputs: every case exits 2 naming the file or value, before any work, and leaves nothing
# behind. The fuzz reproducers (tests/data/fuzz-repro/) through the CLI, the image size limits, one check
# per output kind, and ffmpeg started without a shell.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
REPRO="$(cd "$(dirname "$0")/../data/fuzz-repro" && pwd)"
IMG="$REPRO/../../../fuzz/corpus/hdr/flat_3x2.hdr"

# --- settings and --set
expect 2 "settings with a number beyond double range" -- "$PHOTOPIC" settings --check "$REPRO/settings_1e400.json"
check "the file is named" contains "settings_1e400.json"
check "the overflow is reported" contains "1e400"
expect 2 "--set that is not UTF-8" -- "$PHOTOPIC" image "$IMG" -o "$S/utf8.png" --set $'tonemapping.exposure=\xbe'
check "reported as invalid UTF-8" contains "not valid UTF-8"
check "the text is named" contains 'tonemapping.exposure=\xbe'
check "no output" test ! -e "$S/utf8.png"

# --- image sizes
printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16384 +X 16384\n' > "$S/huge.hdr"
start=$(date +%s%N)
expect 2 "a 53-byte .hdr declaring 16384x16384" -- "$PHOTOPIC" image "$S/huge.hdr" -o "$S/huge.png"
check "rejected before allocating (under 1 s)" test $((($(date +%s%N) - start) / 1000000)) -lt 1000
check "named, as truncated" contains "huge.hdr\": Radiance file is truncated"
python3 -c 'import sys; sys.stdout.buffer.write(b"#?RADIANCE\n\n-Y 4 +X 16385\n" + bytes([128] * 4 * 16385 * 4))' > "$S/wide.hdr"
"$PHOTOPIC" image "$S/wide.hdr" -o "$S/wide.png" > "$S/wide.log" 2>&1
status=$?
OUTPUT=$(cat "$S/wide.log")
if [ $status -eq 0 ] && ! contains "GL_MAX_TEXTURE_SIZE"; then
    echo "skip: this GPU takes textures over 16384 wide, so 16385x4 is not too large here"
else
    check "16385x4 refused for the GPU with exit 2" test $status -eq 2
    check "names the file, the size and the limit" contains "wide.hdr\": image is 16385x4, larger than this GPU's largest texture"
    check "no GL errors on the way" test "$(grep -c GL_INVALID "$S/wide.log")" -eq 0
    check "no output" test ! -e "$S/wide.png"
fi
expect 2 "--max-pixels bounds the input" -- "$PHOTOPIC" image "$IMG" -o "$S/max.png" --max-pixels 5
check "the limit is named" contains "more than the limit of 5 pixels (--max-pixels)"
expect 0 "--max-pixels that fits" -- "$PHOTOPIC" image "$IMG" -o "$S/max.png" --max-pixels 6

# --- every output kind is checked before any work; nothing is left behind
mkdir -p "$S/out/folder"
touch "$S/plainfile"
expect 2 "image: --telemetry names a folder" -- "$PHOTOPIC" image "$IMG" -o "$S/out/t.png" --telemetry "$S/out/folder"
check "telemetry folder named" contains "out/folder\": is a folder"
check "no image left behind" test ! -e "$S/out/t.png"
expect 2 "image: --telemetry in a missing folder" -- "$PHOTOPIC" image "$IMG" -o "$S/out/t.png" --telemetry "$S/out/no/t.csv"
check "no image left behind" test ! -e "$S/out/t.png"
expect 2 "image: output in a missing folder" -- "$PHOTOPIC" image "$IMG" -o "$S/missing/dir/out.png"
check "folder named" contains "does not exist"
check "no folder made" test ! -e "$S/missing"
expect 2 "image: output folder is a file" -- "$PHOTOPIC" image "$IMG" "$IMG" -o "$S/plainfile"

mkdir -p "$S/scene/telemetry.csv"
expect 2 "scene: telemetry.csv is a folder" -- "$PHOTOPIC" scene tabletop --frames 2 --size 64x36 -o "$S/scene"
check "no frames left behind" test ! -e "$S/scene/frame_0000.png"
expect 2 "scene: frames folder is a file" -- "$PHOTOPIC" scene tabletop --frames 2 --size 64x36 -o "$S/plainfile/x"
check "output folder named" contains "plainfile/x"
mkdir -p "$S/scene2/frame_0000.png"
expect 2 "scene: a frame's path is a folder" -- "$PHOTOPIC" scene tabletop --frames 2 --size 64x36 -o "$S/scene2"
check "no telemetry left behind" test ! -e "$S/scene2/telemetry.csv"
# A frame that cannot be written once frames before and after it are being written on worker threads: the
# run fails, takes back every frame it wrote, and keeps the folder that was in the way.
mkdir -p "$S/scene3/frame_0003.png"
expect 1 "scene: a later frame's path is a folder" -- "$PHOTOPIC" scene tabletop --frames 6 --size 64x36 -o "$S/scene3"
check "the frame's path is named" contains "frame_0003.png\": is a folder"
check "no frames left behind" test -z "$(find "$S/scene3" -name 'frame_*.png' -type f)"
check "the folder in the way is kept" test -d "$S/scene3/frame_0003.png"

mkdir -p "$S/plot/exposure_plot.png"
expect 2 "demo: the plot's path is a folder" -- "$PHOTOPIC" demo -o "$S/plot" --size 64x36 --seconds 1 --no-video
check "no frames left behind" test ! -e "$S/plot/frame_0000.png"
mkdir -p "$S/video/demo.mp4"
expect 2 "demo: the video's path is a folder" -- "$PHOTOPIC" demo -o "$S/video" --size 64x36 --seconds 1
check "no frames or telemetry left behind" test ! -e "$S/video/frame_0000.png" -a ! -e "$S/video/telemetry.csv"
expect 2 "demo: frames into a path under a file" -- "$PHOTOPIC" demo -o "$S/plainfile/d" --size 64x36 --seconds 1
mkdir -p "$S/bench.json"
expect 2 "bench: --json is a folder" -- "$PHOTOPIC" bench --size 64x36 --frames 1 --warmup 0 --json "$S/bench.json"
check "refused before timing" contains "bench.json\": is a folder"
check "no temporary files anywhere" test -z "$(find "$S" -name '.*.tmp-*' -o -name '*.tmp')"

# --- ffmpeg is started without a shell: quotes, ';' and $(...) in the output path are only characters
weird="$S/it's; echo hi \$(touch $S/pwned)"
expect 0 "demo into a folder named with ' ; and \$(...)" -- "$PHOTOPIC" demo -o "$weird" --size 64x36 --fps 10 --seconds 1
check "no command from the path ran" test ! -e "$S/pwned"
check "frames written under the literal name" test -s "$weird/frame_0000.png"
if command -v ffmpeg > /dev/null; then
    check "the video was made" test -s "$weird/demo.mp4"
    check "no temporary video left" test -z "$(find "$weird" -name '.demo.mp4.tmp-*')"
else
    echo "skip: ffmpeg is not installed, so no video is encoded (the path was still checked to run nothing)"
    check "the summary says why there is no video" contains "skipped (no ffmpeg command)"
fi

finish

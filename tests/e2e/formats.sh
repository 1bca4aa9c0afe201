#!/usr/bin/env bash
# Display images as TIFF, JPEG and 16-bit PNG/TIFF, chosen by the output's extension: each file is what it says
# (its magic bytes, a 16-bit PNG's IHDR bit depth), a JPEG at 16 bits and other bad values are refused (exit 2,
# the option or file named) before anything is written, and sequences, patterns, folders and scene frames take the
# formats too.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
magic() { head -c "$2" "$1" | od -An -tx1 | tr -d ' \n'; }
pngBitDepth() { od -An -tu1 -j24 -N1 "$1" | tr -d ' '; }

expect 0 "a small EXR to start from" -- "$PHOTOPIC" scene gradient --size 64x48 --frames 2 --format exr -o "$S/in"
expect 0 "EXR to .tif" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/out.tif"
check "a little-endian TIFF" [ "$(magic "$S/out.tif" 4)" = 49492a00 ]
expect 0 "EXR to .jpg" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/out.jpg" --jpeg-quality 80
check "a JPEG" [ "$(magic "$S/out.jpg" 3)" = ffd8ff ]
expect 0 "EXR to a 16-bit .png" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/out16.png" --bit-depth 16
check "a PNG" [ "$(magic "$S/out16.png" 8)" = 89504e470d0a1a0a ]
check "of 16 bits per sample" [ "$(pngBitDepth "$S/out16.png")" = 16 ]
expect 0 "the 16-bit PNG reads back" -- "$PHOTOPIC" image "$S/out16.png" -o "$S/back.exr"
expect 0 "EXR to a 16-bit .tiff" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/out16.tiff" --bit-depth 16
check "larger than the 8-bit TIFF" [ "$(stat -c %s "$S/out16.tiff")" -gt "$(stat -c %s "$S/out.tif")" ]
expect 0 "the default PNG" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/out.png"
expect 0 "--bit-depth 8" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/out8.png" --bit-depth 8
check "is the default, byte for byte" cmp -s "$S/out.png" "$S/out8.png"
check "of 8 bits per sample" [ "$(pngBitDepth "$S/out.png")" = 8 ]

expect 2 "a 16-bit JPEG is refused" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/deep.jpg" --bit-depth 16
check "naming the file, the format and the option" \
    contains "deep.jpg: JPEG holds 8 bits per channel only, but --bit-depth is 16"
check "nothing written" [ ! -e "$S/deep.jpg" ]
expect 2 "output.bitDepth=16 from the settings too" -- \
    "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/deep.jpeg" --set output.bitDepth=16
check "names the setting" contains "output.bitDepth is 16"
expect 2 "--bit-depth 12 is refused" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/x.png" --bit-depth 12
check "naming the value" contains "12"
expect 2 "--jpeg-quality 0 is refused" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/x.jpg" --jpeg-quality 0
check "naming the option" contains "--jpeg-quality"
expect 2 "--set output.bitDepth=12 is refused" -- \
    "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/x.png" --set output.bitDepth=12
check "naming the setting" contains "bitDepth"
expect 2 "an unknown extension is refused" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o "$S/x.bmp"
check "listing the extensions" contains ".tif, .tiff, .jpg or .jpeg"
check "no stray file" [ -z "$(ls "$S" | grep -E '^x\.|^deep|tmp')" ]

expect 0 "a sequence to a 16-bit TIFF pattern" -- \
    "$PHOTOPIC" image "$S/in/frame_%04d.exr" -o "$S/seq/f%04d.tif" --bit-depth 16
check "two TIFFs" [ -s "$S/seq/f0000.tif" -a -s "$S/seq/f0001.tif" ]
expect 0 "a sequence into a folder as JPEG" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" "$S/in/frame_0001.exr" \
    -o "$S/jpgs/" --format jpg
check "two JPEGs" [ "$(magic "$S/jpgs/frame_0001.jpg" 3)" = ffd8ff ]
expect 2 "a stream with --format tif is refused" -- "$PHOTOPIC" image "$S/in/frame_0000.exr" -o - --format tif

expect 0 "scene frames as 16-bit TIFF" -- "$PHOTOPIC" scene gradient --size 64x48 --frames 2 --format tif \
    --bit-depth 16 -o "$S/scene16"
check "two TIFFs" [ "$(magic "$S/scene16/frame_0001.tif" 4)" = 49492a00 ]
expect 2 "scene frames as 16-bit JPEG are refused" -- "$PHOTOPIC" scene gradient --size 64x48 --frames 2 \
    --format jpg --bit-depth 16 -o "$S/scenejpg"
check "naming the frame" contains "frame_0000.jpg: JPEG holds 8 bits per channel only"
check "and leaving no folder" [ ! -e "$S/scenejpg" ]
finish

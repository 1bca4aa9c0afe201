#!/usr/bin/env bash
# `-o` never destroys what it should not: an output that is one of the inputs, two inputs that would share an
# output and a symbolic link are refused before any work (exit 2, the path named), and the input is left as it
# was. `-o -` and devices are streamed, not replaced: one image, a PNG that decodes.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
cp "$DATA/Desk.exr" "$S/desk.exr"
cp "$DATA/Desk.hdr" "$S/desk.hdr"
cp "$DATA/Desk.exr" "$S/seq-a.exr"
before=$(sha256sum "$S/desk.exr" | cut -d' ' -f1)

expect 2 "an output that is the input is refused" -- "$PHOTOPIC" image "$S/desk.exr" -o "$S/desk.exr"
check "names it" contains "is also an input"
check "the input is unchanged" [ "$(sha256sum "$S/desk.exr" | cut -d' ' -f1)" = "$before" ]
expect 2 "the same file through another path is refused" -- "$PHOTOPIC" image "$S/desk.exr" -o "$S/./desk.exr"
expect 2 "two inputs with one stem are refused" -- "$PHOTOPIC" image "$S/desk.exr" "$S/desk.hdr" -o "$S/out/"
check "names both inputs" contains "would both be written to"
check "no folder was made" [ ! -e "$S/out" ]
checks=$((checks + 1))
if "$PHOTOPIC" image "$S/desk.exr" -o - > "$S/stdout.png" 2> "$S/stderr.txt"; then
    echo "ok: -o - writes to standard output"
else
    echo "FAIL: -o - writes to standard output"
    failures=$((failures + 1))
fi
check "no file or folder named -" [ ! -e "-" ]
check "the lines printed went to standard error" grep -q "desk.exr -> -" "$S/stderr.txt"
check "it is a PNG" [ "$(head -c 8 "$S/stdout.png" | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ]
expect 0 "the PNG from standard output decodes" -- "$PHOTOPIC" image "$S/stdout.png" -o "$S/decoded.exr"
expect 0 "the same image as a file" -- "$PHOTOPIC" image "$S/desk.exr" -o "$S/file.png"
check "byte-identical to -o -" cmp -s "$S/file.png" "$S/stdout.png"
"$PHOTOPIC" image "$S/desk.exr" -o /dev/stdout > "$S/devstdout.png" 2> /dev/null
check "/dev/stdout redirected to a file: the same bytes" cmp -s "$S/file.png" "$S/devstdout.png"
"$PHOTOPIC" image "$S/desk.exr" -o "$S/t.png" --telemetry "$S/t.csv" > /dev/null 2>&1
"$PHOTOPIC" image "$S/desk.exr" -o "$S/t.png" --telemetry - > "$S/t-stdout.csv" 2> /dev/null
check "--telemetry - streams the same CSV" cmp -s "$S/t.csv" "$S/t-stdout.csv"
expect 2 "the image and the telemetry both to standard output is refused" -- \
    "$PHOTOPIC" image "$S/desk.exr" -o - --telemetry -
expect 2 "-o - with several inputs is refused" -- "$PHOTOPIC" image "$S/desk.exr" "$S/desk.hdr" -o -
check "says a stream holds one image" contains "holds one image, not 2"
expect 2 "several inputs and one image file name are refused" -- \
    "$PHOTOPIC" image "$S/desk.exr" "$S/desk.hdr" -o "$S/both.png"
check "says a folder or a pattern is needed" contains "names one image file, and there are 2 inputs"
check "no folder was made" [ ! -e "$S/both.png" ]
mkdir -p "$S/renders.png"
expect 0 "an existing folder with a dot in its name still takes several inputs" -- \
    "$PHOTOPIC" image "$S/seq-a.exr" "$S/desk.hdr" -o "$S/renders.png" --set tonemapping.mode=neutral
check "the first result in it" [ -f "$S/renders.png/seq-a.png" ]
check "the second result in it" [ -f "$S/renders.png/desk.png" ]
expect 0 "a device is streamed to" -- "$PHOTOPIC" image "$S/desk.exr" -o /dev/null
check "and left a device" [ -c /dev/null ]
mkfifo "$S/pipe.png"
cat "$S/pipe.png" > "$S/from-pipe.png" &
expect 0 "a named pipe is streamed to" -- "$PHOTOPIC" image "$S/desk.exr" -o "$S/pipe.png"
wait
check "the reader got the PNG" cmp -s "$S/file.png" "$S/from-pipe.png"
check "the pipe is still a pipe" [ -p "$S/pipe.png" ]
ln -s "$S/target.png" "$S/link.png"
expect 2 "a symbolic link is refused" -- "$PHOTOPIC" image "$S/desk.exr" -o "$S/link.png"
check "says why" contains "symbolic link"
check "the link is still a link" [ -L "$S/link.png" ]
expect 0 "a plain output still works" -- "$PHOTOPIC" image "$S/desk.exr" -o "$S/desk.png"

# Frames in natural order: f9 before f10 (a string sort would run f10 first).
mkdir -p "$S/seq"
for n in 9 10 1; do cp "$S/desk.exr" "$S/seq/f$n.exr"; done
expect 0 "a sequence in natural order" -- "$PHOTOPIC" image "$S/seq/f10.exr" "$S/seq/f9.exr" "$S/seq/f1.exr" -o "$S/seqout/"
check "f1, f9, f10" [ "$(grep -o 'seq/f[0-9]*\.exr ->' <<< "$OUTPUT" | tr -d '\n')" = "seq/f1.exr ->seq/f9.exr ->seq/f10.exr ->" ]
expect 0 "--version" -- "$PHOTOPIC" --version
check "prints the version" contains "photopic 0."
expect 0 "photopic-view --version (no display needed)" -- "$(dirname "$PHOTOPIC")/photopic-view" --version
check "prints its version" contains "photopic-view 0."
finish

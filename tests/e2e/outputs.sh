#!/usr/bin/env bash
# `-o` never destroys what it should not: an output that is one of the inputs, two inputs that would share an
# output, `-`, a device such as /dev/stdout and a symbolic link are refused before any work (exit 2, the path
# named), and the input is left as it was.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
cp "$DATA/Desk.exr" "$S/desk.exr"
cp "$DATA/Desk.hdr" "$S/desk.hdr"
before=$(sha256sum "$S/desk.exr" | cut -d' ' -f1)

expect 2 "an output that is the input is refused" -- "$PHOTOPIC" image "$S/desk.exr" -o "$S/desk.exr"
check "names it" contains "is also an input"
check "the input is unchanged" [ "$(sha256sum "$S/desk.exr" | cut -d' ' -f1)" = "$before" ]
expect 2 "the same file through another path is refused" -- "$PHOTOPIC" image "$S/desk.exr" -o "$S/./desk.exr"
expect 2 "two inputs with one stem are refused" -- "$PHOTOPIC" image "$S/desk.exr" "$S/desk.hdr" -o "$S/out/"
check "names both inputs" contains "would both be written to"
check "no folder was made" [ ! -e "$S/out" ]
expect 2 "-o - is refused, not a folder named -" -- "$PHOTOPIC" image "$S/desk.exr" -o -
check "no file or folder named -" [ ! -e "-" ]
expect 2 "a device is refused" -- "$PHOTOPIC" image "$S/desk.exr" -o /dev/null
check "says it is not a file" contains "device, pipe or socket"
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

#!/usr/bin/env bash
# Sequences named as ffmpeg and oiiotool users name them: input patterns (f%04d.exr, f####.exr, f@.exr) with a
# frame range (--frames A-B) or a start number, output patterns (-o out/f%04d.png), and -n/-y for outputs that
# exist. A pattern gives the same frames, outputs and telemetry, byte for byte, as the files it names listed
# one by one; a pattern that matches nothing, a missing frame of a range and an output that -n forbids are
# refused before any work (exit 2, named).
source "$(dirname "$0")/lib.bash"
cd "$SCRATCH"

expect 0 "make an adapting sequence" -- "$PHOTOPIC" scene tabletop --format exr --size 96x54 --frames 6 -o src
mkdir seq useq
for i in 0 1 2 3 4 5; do
    cp "src/frame_000$i.exr" "seq/f$((1001 + i)).exr"
    cp "src/frame_000$i.exr" "useq/u$((8 + i)).exr" # u8 ... u13: unpadded, f9 before f10
done
cp src/frame_0000.exr useq/u08.exr # printf("%d") never writes 08: not a frame of u@.exr
AE=(--set autoExposure.enabled=true --tonemap aces-fitted)
lines() { grep -o '^[^ ]*\.[a-z]* -> [^ ]*' <<< "$OUTPUT" | tr '\n' ' '; } # the frames, not the telemetry
same_files() { # same_files A B: the same names with the same bytes
    [ "$(ls "$1")" = "$(ls "$2")" ] && (cd "$1" && sha256sum -- *) | (cd "$2" && sha256sum --quiet -c -)
}

expect 0 "the frames as a file list" -- "$PHOTOPIC" image seq/f1001.exr seq/f1002.exr seq/f1003.exr \
    seq/f1004.exr seq/f1005.exr seq/f1006.exr -o list/ "${AE[@]}" --telemetry list.csv
for run in 'pct:seq/f%04d.exr' 'hash:seq/f####.exr'; do
    name=${run%%:*} pattern=${run#*:}
    expect 0 "$pattern" -- "$PHOTOPIC" image "$pattern" -o "$name/" "${AE[@]}" --telemetry "$name.csv"
    check "$pattern: six frames in frame order" [ "$(lines)" = "$(for f in 1001 1002 1003 1004 1005 1006; do
        printf 'seq/f%s.exr -> %s/f%s.png ' $f "$name" $f
    done)" ]
    check "$pattern: outputs byte-identical to the file list's" same_files list "$name"
    check "$pattern: telemetry identical" cmp -s list.csv "$name.csv"
done

expect 0 "@ is unpadded" -- "$PHOTOPIC" image 'useq/u@.exr' -o uout/
check "u8 ... u13 in numeric order, u08 left out" [ "$(lines)" = "useq/u8.exr -> uout/u8.png useq/u9.exr -> uout/u9.png \
useq/u10.exr -> uout/u10.png useq/u11.exr -> uout/u11.png useq/u12.exr -> uout/u12.png useq/u13.exr -> uout/u13.png " ]

expect 0 "--frames 1002-1004" -- "$PHOTOPIC" image 'seq/f%04d.exr' --frames 1002-1004 -o range/ "${AE[@]}" \
    --telemetry range.csv
check "three frames" [ "$(lines)" = "seq/f1002.exr -> range/f1002.png seq/f1003.exr -> range/f1003.png \
seq/f1004.exr -> range/f1004.png " ]
expect 0 "the same three as files" -- "$PHOTOPIC" image seq/f1002.exr seq/f1003.exr seq/f1004.exr -o range-list/ \
    "${AE[@]}" --telemetry range-list.csv
check "a range: outputs byte-identical to its files'" same_files range-list range
check "a range: telemetry identical" cmp -s range-list.csv range.csv
expect 0 "--start-number 1004" -- "$PHOTOPIC" image 'seq/f####.exr' --start-number 1004 -o start/
check "frames 1004 to the last" [ "$(ls start | tr '\n' ' ')" = "f1004.png f1005.png f1006.png " ]

mkdir gap
cp seq/f1001.exr seq/f1002.exr seq/f1005.exr gap/
expect 0 "a pattern with a gap runs the frames that exist" -- "$PHOTOPIC" image 'gap/f%04d.exr' -o gapout/
check "and warns, naming the first missing frame" contains "2 frame(s) missing between 1001 and 1005, the first 1003"
check "three frames written" [ "$(ls gapout | wc -l)" = 3 ]

# Output patterns: the inputs' frame numbers, or 0, 1, ... when the inputs carry none.
expect 0 "-o out/f%04d.png" -- "$PHOTOPIC" image 'seq/f%04d.exr' -o pat/g%04d.png "${AE[@]}"
check "named by the input frames, same bytes as the folder output" \
    [ "$(ls pat | tr '\n' ' ')" = "g1001.png g1002.png g1003.png g1004.png g1005.png g1006.png " ]
check "same bytes as the folder output" cmp -s pat/g1003.png list/f1003.png
expect 0 "an output pattern from a file list with numbers" -- "$PHOTOPIC" image seq/f1005.exr seq/f1006.exr -o pat2/x.#.png
check "their numbers" [ "$(ls pat2 | tr '\n' ' ')" = "x.1005.png x.1006.png " ]
cp "$DATA/Desk.exr" desk.exr
cp "$DATA/Desk.hdr" room.hdr
expect 0 "an output pattern from inputs without numbers" -- "$PHOTOPIC" image room.hdr desk.exr -o pat3/v%03d.exr
check "0-based, in input order" [ "$(lines)" = "desk.exr -> pat3/v000.exr room.hdr -> pat3/v001.exr " ]

mkdir 'take@2#'
expect 0 "a folder named with @ and # is a folder, not a pattern" -- "$PHOTOPIC" image desk.exr -o 'take@2#/desk.png'
check "written there" [ -f 'take@2#/desk.png' ]
expect 0 "a '%' that is no frame number is part of the name" -- "$PHOTOPIC" image desk.exr -o '50%.png'
check "written as named" [ -f '50%.png' ]
cp desk.exr 'shot#1.exr'
expect 0 "an input that exists is a file, whatever its name holds" -- "$PHOTOPIC" image 'shot#1.exr' -o shot.png

# Refusals, before any work.
expect 2 "a pattern that matches no file" -- "$PHOTOPIC" image 'seq/h%04d.exr' -o none/
check "names the pattern" contains 'seq/h%04d.exr'
expect 2 "a range with a missing frame" -- "$PHOTOPIC" image 'seq/f%04d.exr' --frames 1005-1008 -o none/
check "names the first missing file" contains "seq/f1007.exr"
expect 2 "a start number past the last frame" -- "$PHOTOPIC" image 'seq/f%04d.exr' --start-number 2000 -o none/
expect 2 "a bad range" -- "$PHOTOPIC" image 'seq/f%04d.exr' --frames 1006-1001 -o none/
check "says so" contains "--frames"
expect 2 "--frames with file inputs" -- "$PHOTOPIC" image seq/f1001.exr --frames 1-2 -o none/
expect 2 "--frames and --start-number together" -- "$PHOTOPIC" image 'seq/f%04d.exr' --frames 1001-1002 \
    --start-number 1001 -o none/
expect 2 "two frame numbers in a name" -- "$PHOTOPIC" image 'seq/f%04d_%d.exr' -o none/
check "nothing was made by the refused runs" [ ! -e none ]
expect 2 "an output pattern that names the inputs" -- "$PHOTOPIC" image 'seq/f%04d.exr' -o 'seq/f%04d.exr'
check "says so" contains "is also an input"

# Outputs that exist: replaced by default and with -y, refused with -n.
before=$(sha256sum pat/g1001.png)
touch -d '2001-01-01' pat/g1001.png
expect 2 "-n refuses an output that exists" -- "$PHOTOPIC" image 'seq/f%04d.exr' -o pat/g%04d.png -n
check "names it" contains "pat/g1001.png exists"
check "before any work: no frame processed" [ -z "$(lines)" ]
check "the file is untouched" [ "$(stat -c %Y pat/g1001.png)" = "$(date -d '2001-01-01' +%s)" ]
expect 2 "-n refuses a telemetry CSV that exists" -- "$PHOTOPIC" image 'seq/f%04d.exr' -o new/ -n --telemetry list.csv
check "names it" contains "list.csv exists"
check "no folder made" [ ! -e new ]
expect 0 "-n with new outputs" -- "$PHOTOPIC" image 'seq/f%04d.exr' --frames 1001-1001 -o new/ -n
expect 2 "-n and -y together" -- "$PHOTOPIC" image 'seq/f%04d.exr' -o pat/g%04d.png -n -y
expect 0 "-y replaces" -- "$PHOTOPIC" image 'seq/f%04d.exr' -o pat/g%04d.png -y "${AE[@]}"
check "replaced" [ "$(stat -c %Y pat/g1001.png)" != "$(date -d '2001-01-01' +%s)" ]
check "with the same image" [ "$(sha256sum pat/g1001.png)" = "$before" ]
touch -d '2001-01-01' pat/g1001.png
expect 0 "the default replaces too" -- "$PHOTOPIC" image 'seq/f%04d.exr' -o pat/g%04d.png "${AE[@]}"
check "replaced" [ "$(stat -c %Y pat/g1001.png)" != "$(date -d '2001-01-01' +%s)" ]
check "no temporary files" test -z "$(find . -name '.*.tmp-*')"
finish

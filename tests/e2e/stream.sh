#!/usr/bin/env bash
# photopic image streams a sequence (decode ahead, write behind on other threads): whatever the number of
# frames in flight, every output, the telemetry CSV and the order of the lines printed are those of the
# serial run (--frames-in-flight 1), whatever the decode pool's size, and a bad frame part way still leaves
# nothing behind.
source "$(dirname "$0")/lib.bash"
cd "$SCRATCH"

# An adapting sequence (the tabletop's light changes) with a frame of another size in the middle (a resize).
expect 0 "make the sequence" -- "$PHOTOPIC" scene tabletop --format exr --size 96x54 --frames 12 -o src
cp "$DATA/Desk.exr" src/frame_0005b.exr
AE=(--set autoExposure.enabled=true --tonemap aces-fitted)

expect 0 "serial" -- "$PHOTOPIC" image src/*.exr -o serial "${AE[@]}" --telemetry serial.csv --frames-in-flight 1
serial_lines=$(grep -o '^src/[^ ]* -> [^ ]*' <<< "$OUTPUT")
check "13 frames, in name order" [ "$(wc -l <<< "$serial_lines")" = 13 ]
check "frame_0005b between frame_0005 and frame_0006" \
    [ "$(grep -o '^src/frame_000[56]b\?' <<< "$serial_lines" | tr '\n' ' ')" = \
        "src/frame_0005 src/frame_0005b src/frame_0006 " ]

same_outputs() { # same_outputs DIR: every file of serial/ is in DIR with the same bytes, and nothing else
    [ "$(ls serial | wc -l)" = 13 ] && [ "$(ls serial)" = "$(ls "$1")" ] && (cd serial && sha256sum -- *) | (cd "$1" && sha256sum --quiet -c -)
}

for n in 2 3 5; do
    expect 0 "$n frames in flight" -- "$PHOTOPIC" image src/*.exr -o "streamed$n" "${AE[@]}" \
        --telemetry "streamed$n.csv" --frames-in-flight "$n"
    check "$n in flight: frames printed in the serial order" \
        [ "$(grep -o '^src/[^ ]* -> [^ ]*' <<< "$OUTPUT" | sed "s/streamed$n/serial/")" = "$serial_lines" ]
    check "$n in flight: every frame byte-identical to the serial run's" same_outputs "streamed$n"
    check "$n in flight: telemetry identical" cmp -s serial.csv "streamed$n.csv"
done

# The decode pool's size changes who decodes, not what: none (each frame's chunks on the decode thread) and
# more threads than the frame has chunks.
for t in 0 7; do
    expect 0 "decode threads $t" -- "$PHOTOPIC" image src/*.exr -o "threads$t" "${AE[@]}" \
        --telemetry "threads$t.csv" --frames-in-flight 3 --decode-threads "$t"
    check "decode threads $t: every frame byte-identical to the serial run's" same_outputs "threads$t"
    check "decode threads $t: telemetry identical" cmp -s serial.csv "threads$t.csv"
done
expect 2 "decode threads out of range" -- "$PHOTOPIC" image src/*.exr -o bad --decode-threads 257
check "names the option" contains "--decode-threads"
check "nothing written" test ! -e bad

expect 0 "EXR outputs, serial" -- "$PHOTOPIC" image src/*.exr -o exr1 --format exr "${AE[@]}" --frames-in-flight 1
expect 0 "EXR outputs, streamed" -- "$PHOTOPIC" image src/*.exr -o exr3 --format exr "${AE[@]}"
check "13 EXR frames" [ "$(ls exr1 | wc -l)" = 13 ]
check "EXR frames byte-identical" [ "$( (cd exr1 && sha256sum -- *) )" = "$( (cd exr3 && sha256sum -- *) )" ]

# A truncated frame part way: the frames written before it are taken back with the folder.
head -c 2000 src/frame_0008.exr > src/frame_0008c.exr
expect 2 "a truncated frame part way" -- "$PHOTOPIC" image src/*.exr -o broken "${AE[@]}" --telemetry broken.csv
check "names the file" contains "frame_0008c.exr"
check "no frames, no folder left" test ! -e broken
check "no telemetry left" test ! -e broken.csv
check "no temporary files" test -z "$(find . -name '.*.tmp-*')"
finish

#!/usr/bin/env bash
# The CLI's commands, outputs and exit codes (0 ok, 2 bad usage or input, 1 other failure).
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"

expect 0 "info runs" -- "$PHOTOPIC" info
check "info names the renderer and colour path" contains "GL renderer:"
check "info says HDR or LDR and why" contains "colour path:"
expect 0 "info --force-ldr" -- "$PHOTOPIC" info --force-ldr
check "forced LDR is reported" contains "LDR, RGBA8"
# A production context unless asked: --gl-debug (before or after the command) or PHOTOPIC_GL_DEBUG=1.
expect 0 "info without a debug context" -- env -u PHOTOPIC_GL_DEBUG "$PHOTOPIC" info
check "info says GL debug output is off" contains "GL debug:     off"
expect 0 "info --gl-debug" -- "$PHOTOPIC" info --gl-debug
check "--gl-debug makes a debug context" contains "GL debug:     on"
expect 0 "--gl-debug before the command" -- "$PHOTOPIC" --gl-debug info
check "--gl-debug before the command too" contains "GL debug:     on"
expect 0 "PHOTOPIC_GL_DEBUG=1" -- env PHOTOPIC_GL_DEBUG=1 "$PHOTOPIC" info
check "PHOTOPIC_GL_DEBUG=1 makes a debug context" contains "GL debug:     on"

expect 2 "no subcommand is bad usage" -- "$PHOTOPIC"
expect 2 "unknown option is bad usage" -- "$PHOTOPIC" image --bogus
expect 0 "--help" -- "$PHOTOPIC" image --help

expect 0 "EXR to PNG" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/desk.png" --tonemap agx --exposure -2
check "PNG written" test -s "$S/desk.png"
expect 0 "HDR to EXR (scene-referred)" -- "$PHOTOPIC" image "$DATA/Desk.hdr" -o "$S/desk.exr" --set tonemapping.exposure=-1
check "EXR written" test -s "$S/desk.exr"
expect 0 "EXR output reads back as input" -- "$PHOTOPIC" image "$S/desk.exr" -o "$S/desk2.png"

mkdir -p "$S/seq"
expect 0 "several inputs into a folder" -- "$PHOTOPIC" image "$DATA/GoldenGate.exr" "$DATA/Desk.exr" -o "$S/seq" --set tonemapping.mode=neutral
check "one PNG per input" test -s "$S/seq/GoldenGate.png" -a -s "$S/seq/Desk.png"

expect 2 "missing input" -- "$PHOTOPIC" image "$S/nope.exr" -o "$S/nope.png"
check "error names the file" contains "nope.exr"
check "no output for a missing input" test ! -e "$S/nope.png"

head -c 5000 "$DATA/Desk.exr" > "$S/truncated.exr"
expect 2 "truncated EXR" -- "$PHOTOPIC" image "$S/truncated.exr" -o "$S/truncated.png"
check "error names the truncated file" contains "truncated.exr"
check "no output for a truncated input" test ! -e "$S/truncated.png"

expect 2 "bad tone curve" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/bad.png" --tonemap filmic
check "error names the key and the allowed values" contains "postEffects.tonemapping.mode"
check "allowed values listed" contains "aces-fitted"
check "and the option as typed" contains "invalid settings in --tonemap filmic"
expect 2 "out-of-range exposure" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/bad.png" --set tonemapping.exposure=99
check "range named" contains "[-20, 20]"
expect 2 "unknown key" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/bad.png" --set tonemapping.gamma=2
check "unknown key named" contains "postEffects.tonemapping.gamma"
expect 2 "unsupported output extension" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/out.bmp"
check "no output for bad settings" test ! -e "$S/bad.png"
expect 2 "output folder that does not exist" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/missing/dir/out.png"
check "no partial output" test ! -e "$S/missing/dir/out.png"

expect 0 "settings --defaults" -- "$PHOTOPIC" settings --defaults
echo "$OUTPUT" > "$S/defaults.json"
check "defaults carry the version" contains '"version": 1'
expect 0 "defaults pass --check" -- "$PHOTOPIC" settings --check "$S/defaults.json"
echo '{"version": 1, "postEffects": {"tonemapping": {"mode": "agx", "exposure": "bright"}, "output": {"dithering": true}}}' > "$S/bad.json"
expect 2 "bad settings file" -- "$PHOTOPIC" settings --check "$S/bad.json"
check "wrong type named by path" contains "postEffects.tonemapping.exposure"
check "unknown key named by path" contains "postEffects.output.dithering"
check "file named" contains "bad.json"
expect 0 "settings file drives the image" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/fromfile.png" --settings "$S/defaults.json"

finish

#!/usr/bin/env bash
# How the CLI talks: the progress line (on a terminal only, never in a pipe or with -q), -q/-v/--log-level, enum
# names and examples in --help, the README's canvas --motion command, and the settings messages a new user meets
# first (a missing file, an unknown key).
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
lacks() { [[ "$OUTPUT" != *"$1"* ]]; }

# on_pty command...: runs the command with stdout and stderr on a pseudo-terminal (python3's pty module) and keeps
# everything it wrote there in $OUTPUT; returns its exit code.
on_pty() {
    OUTPUT=$(python3 - "$@" <<'EOF'
import os, pty, subprocess, sys
master, slave = pty.openpty()
child = subprocess.Popen(sys.argv[1:], stdin=subprocess.DEVNULL, stdout=slave, stderr=slave)
os.close(slave)
out = b""
while True:
    try:
        data = os.read(master, 65536)
    except OSError:  # EIO: the child's side of the terminal is closed
        break
    if not data:
        break
    out += data
sys.stdout.write(out.decode("utf-8", "replace"))
sys.exit(child.wait())
EOF
    )
}

# The CPU ray tracer's colour reference: CPU-bound, so it runs past a second on any GPU (about 5 s on llvmpipe's
# 2 cores), which is what shows the line.
LONG=(scene testbed --truth color --size 200x112 --frames 4)
checks=$((checks + 1))
if on_pty "$PHOTOPIC" "${LONG[@]}" -o "$S/truth_tty"; then echo "ok: long work on a terminal"; else
    echo "FAIL: long work on a terminal"
    failures=$((failures + 1))
fi
check "a progress line on the terminal" contains "scene testbed --truth: "
check "it counts what is done" contains "/4 images"
check "it gives the rate and the time left" contains " images/s, ETA "
check "the results are still printed" contains "testbed truth: 1 kind(s) x 4 frame(s)"
on_pty "$PHOTOPIC" "${LONG[@]}" -o "$S/truth_quiet" -q
check "-q on a terminal: no progress line" lacks "images/s"
check "-q prints errors only: no line per image" lacks "truth_color_"
check "-q prints errors only: no summary" lacks "testbed truth:"
check "-q wrote the work all the same" test -s "$S/truth_quiet/truth_color_0003.exr"
expect 0 "the same work into a pipe" -- "$PHOTOPIC" "${LONG[@]}" -o "$S/truth_pipe"
check "no progress line in a pipe" lacks "images/s"
check "no terminal control codes in a pipe" lacks $'\e[K'
expect 0 "-q on an image sequence" -- "$PHOTOPIC" image "$S/truth_pipe/truth_color_%04d.exr" -o "$S/quiet/" -q
check "-q: nothing printed for a sequence of frames" test -z "$OUTPUT"

# -q, -v and --log-level, before or after the command's name.
expect 0 "-v prints debug messages" -- "$PHOTOPIC" scene gradient -o "$S/verbose" --frames 2 --size 32x18 -v
check "each frame written is logged" contains "photopic debug: frame 1 -> "
expect 0 "--log-level before the command" -- "$PHOTOPIC" --log-level warning scene gradient -o "$S/level" \
    --frames 2 --size 32x18
check "no debug messages at warning" lacks "photopic debug:"
expect 2 "an unknown log level is bad usage" -- "$PHOTOPIC" scene gradient --log-level loud
check "the levels are listed" contains "debug,info,warning,error"

# Every enum option lists its names; every command shows examples.
for command in image scene; do
    expect 0 "$command --help" -- "$PHOTOPIC" "$command" --help
    for name in linear reinhard-extended hable aces-fitted agx neutral; do
        check "$command --help lists the tone curve $name" contains "$name"
    done
    for name in histogram metering bloom normals taa-history-weight velocity-tiles volumetric-light; do
        check "$command --help lists the debug view $name" contains "$name"
    done
    check "$command --help shows examples" contains "Examples:"
    check "$command --help shows -q" contains "-q,--quiet"
    check "$command --help shows --log-level" contains "--log-level"
done
check "scene --help lists the truth kinds" contains "thinlens, reflection, or all"
for name in gradient canvas tabletop testbed; do
    check "scene --help names the scene $name" contains "$name"
done
expect 0 "image --help" -- "$PHOTOPIC" image --help
check "image --help lists --jitter's names" contains "{attribute,halton}"
for command in info settings demo bench; do
    expect 0 "$command --help" -- "$PHOTOPIC" "$command" --help
    check "$command --help shows examples" contains "Examples:"
done
VIEW="$(dirname "$PHOTOPIC")/photopic-view" # built only where GLFW and Dear ImGui are installed
if [ -x "$VIEW" ]; then
    expect 0 "photopic-view --help" -- "$VIEW" --help
    check "photopic-view takes -q, -v and --log-level" contains "-v,--verbose"
fi

# The README's canvas command, as written there, from the repository root (its --motion file ships).
readme=$(grep -o 'photopic scene canvas -o out/canvas [^#]*--motion examples/[^ ]*\.csv' "$ROOT/README.md")
check "the README has the canvas --motion command" test -n "$readme"
read -r -a words <<< "${readme#photopic }"
words=("${words[@]/#out\/canvas/$S/canvas}")
cd "$ROOT" || exit 1
expect 0 "the README's canvas --motion command runs" -- "$PHOTOPIC" "${words[@]}"
check "its frames are written" test -s "$S/canvas/frame_0059.png"
# The built-in scripted tilt keeps yaw at 0; the sample's yaw grows by 0.05 rad/s.
check "the motion file drove the scene (telemetry's yaw column moves)" \
    awk -F, 'NR > 2 && $5 > 0 { moved = 1 } END { exit !moved }' "$S/canvas/telemetry.csv"
check "the sample's units are documented" grep -q "radians" "$ROOT/examples/canvas-motion/README.md"
cd - > /dev/null || exit 1

# Settings messages: a missing file is named as missing; an unknown key reads once, with its place and the keys.
expect 2 "settings --check of a missing file" -- "$PHOTOPIC" settings --check "$S/no_such.json"
check "it says the file does not exist" contains "settings file $S/no_such.json does not exist"
check "it is not called invalid JSON" lacks "JSON"
expect 2 "--settings naming a missing file" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/x.png" \
    --settings "$S/no_such.json"
check "the file is named as missing" contains "does not exist: $S/no_such.json"
echo '{"version": 1, "postEffects": {"bloom": {"foo": 1}}}' > "$S/foo.json"
expect 2 "an unknown key" -- "$PHOTOPIC" settings --check "$S/foo.json"
check "the key, where it is and the known keys" contains "postEffects.bloom.foo: unknown key (known keys: enabled"
check "'unknown key' is said once" test "$(grep -o "unknown key" <<< "$OUTPUT" | wc -l)" -eq 1

finish

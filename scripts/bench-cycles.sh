#!/usr/bin/env bash
# The 3D effects' presets on a renderer's frame rather than the bench's synthetic one: Debian's blender renders
# the interop scene (tests/interop/blender/scene.py: ground, wall, boxes, spheres, a sun; Cycles) at SIZE, its
# camera track is exported (tools/blender/photopic_camera.py), and `photopic bench` times each 3D effect at each
# preset on frame 3's own depth, normals, motion and camera, the presets interleaved in ROUNDS rounds. Writes
# OUT/render/ (the EXRs, scene.blend, track.json), OUT/EFFECT-PRESET-rN.json and OUT/summary.md: per effect and
# preset the effect's passes summed (ms, over the rounds) and against the default preset in the same round.
# Usage: scripts/bench-cycles.sh OUT PHOTOPIC [SIZE]   SIZE 1920x1080 by default. Environment: SAMPLES (Cycles
# samples, 16: the effects read depth, normals and motion, which need few), ROUNDS (2), FRAMES (3),
# BENCH_ARGS (--sync, for a software renderer; --queue-ahead on a GPU).
set -euo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 OUT PHOTOPIC [SIZE]" >&2
    exit 2
fi
out=$1 photopic=$2 size=${3:-1920x1080}
samples=${SAMPLES:-16} rounds=${ROUNDS:-2} frames=${FRAMES:-3}
read -r -a bench_args <<< "${BENCH_ARGS:---sync}"
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$out"
if [ ! -f "$out/render/passes/frame_0003.exr" ] || [ ! -f "$out/render/track.json" ]; then
    blender -b --factory-startup --python "$root/tests/interop/blender/scene.py" -- --out "$out/render" \
        --variant passes --size "$size" --samples "$samples"
    blender -b "$out/render/scene.blend" --python "$root/tools/blender/photopic_camera.py" -- \
        -o "$out/render/track.json"
fi

run() { # NAME bench-settings...
    local name=$1
    shift
    "$photopic" bench --input "$out/render/passes/frame_0003.exr" --camera "$out/render/track.json" \
        --frames "$frames" --warmup 3 "${bench_args[@]}" --json "$out/$name.json" "$@" > /dev/null
}
for round in $(seq 1 "$rounds"); do
    for effect in ssao contactShadows ssr volumetricLight motionBlur; do
        for preset in low medium high ultra; do
            run "$effect-$preset-r$round" --set "$effect.enabled=true" --set "$effect.quality=$preset"
        done
    done
    for preset in low medium high; do
        run "dof-$preset-r$round" --set dof.enabled=true --set dof.quality="$preset"
    done
    for filter in catmull-rom bilinear; do
        run "taa-$filter-r$round" --set aa.mode=taa --set taa.historyFilter="$filter"
    done
    echo "round $round done"
done

python3 - "$out" "$rounds" > "$out/summary.md" <<'PY'
import json, sys
out, rounds = sys.argv[1], int(sys.argv[2])
effects = [("ssao", "gtao", ["low", "medium", "high", "ultra"], "high"),
           ("contactShadows", "contact shadow", ["low", "medium", "high", "ultra"], "high"),
           ("ssr", "ssr", ["low", "medium", "high", "ultra"], "high"),
           ("volumetricLight", "volumetric light", ["low", "medium", "high", "ultra"], "high"),
           ("motionBlur", "motion blur", ["low", "medium", "high", "ultra"], "high"),
           ("dof", "dof", ["low", "medium", "high"], "medium"),
           ("taa", "taa", ["catmull-rom", "bilinear"], "catmull-rom")]

def total(name, prefix):
    d = json.load(open(f"{out}/{name}.json"))
    key = "medianWallMs" if d.get("sync") else "medianGpuMs"
    return d, sum(p.get(key, 0.0) for p in d["passes"] if p["name"].startswith(prefix))

first, _ = total("ssao-high-r1", "gtao")
print(f"{first['width']}x{first['height']}, {first['input']} (3D inputs: {first['inputs3d']}), "
      f"{first['renderer']}, {rounds} round(s)\n")
print("| effect | preset | ms (each round) | against the default, same round |")
print("|---|---|---|---|")
for effect, prefix, presets, default in effects:
    for preset in presets:
        ms = [total(f"{effect}-{preset}-r{r}", prefix)[1] for r in range(1, rounds + 1)]
        base = [total(f"{effect}-{default}-r{r}", prefix)[1] for r in range(1, rounds + 1)]
        ratio = [m / b for m, b in zip(ms, base) if b > 0]
        print(f"| {effect} | {preset} | {', '.join(f'{m:.2f}' for m in ms)} | "
              f"{', '.join(f'{r:.2f}' for r in ratio)} |")
PY
cat "$out/summary.md"

#!/usr/bin/env bash
# `make bench`: the pipeline's per-pass table at 720p, 1080p, 4K and 8K (each beside its own copy reference,
# bench --json written to out/bench/SIZE.json and the console table to out/bench/SIZE.txt), then one summary
# table of the chain's time (the sum of the passes' GPU times, and the whole frame between one pair of
# timestamps) per frame and per megapixel (out/bench/scaling.md): the cost should grow linearly
# with pixels. Usage: scripts/bench-table.sh PHOTOPIC FRAMES [SIZES...] [-- bench options]; on a GPU,
# `-- --queue-ahead` times the GPU's own work (each JSON then carries the frame as submitted too).
set -euo pipefail
photopic=$1 frames=$2
shift 2
sizes=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do sizes+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
[ ${#sizes[@]} -gt 0 ] || sizes=(1280x720 1920x1080 3840x2160 7680x4320)
out=out/bench
mkdir -p "$out"
for size in "${sizes[@]}"; do
    "$photopic" bench --size "$size" --frames "$frames" --json "$out/$size.json" "$@" | tee "$out/$size.txt"
done
python3 - "$out" "${sizes[@]}" > "$out/scaling.md" <<'PY'
import json, sys
out, sizes = sys.argv[1], sys.argv[2:]
rows = [json.load(open(f"{out}/{s}.json")) for s in sizes]
print(f"Device: {rows[0]['renderer']} ({rows[0]['driver']})\n")
print("| size | megapixels | passes ms | whole frame ms | ms per megapixel | copy GB/s | passes GB/s | of copy |")
print("|---|---|---|---|---|---|---|---|")
for s, d in zip(sizes, rows):
    mp = d["width"] * d["height"] / 1e6
    ms = d["totalMedianGpuMs"]
    copy = d["copyReference"]["gbPerSecond"]
    gbps = d["totalBytesMoved"] / (ms * 1e6) if ms > 0 else 0
    frame = d.get("frameMedianGpuMs", 0.0)
    print(f"| {s} | {mp:.2f} | {ms:.3f} | {frame:.3f} | {frame / mp:.3f} | {copy:.1f} | {gbps:.1f} | "
          f"{100 * gbps / copy:.0f}% |")
PY
cat "$out/scaling.md"

#!/usr/bin/env bash
# Soak: renders FRAMES tabletop frames at 64x36 and checks that resident memory stays flat.
# Usage: scripts/soak.sh PHOTOPIC FRAMES MAX_GROWTH_KB
set -euo pipefail
photopic="$1"
frames="$2"
max_growth_kb="$3"
out="$(mktemp -d "${TMPDIR:-/tmp}/photopic-soak.XXXXXX")"
trap 'rm -rf "$out"' EXIT
start=$(date +%s)
"$photopic" scene tabletop --frames "$frames" --size 64x36 --every 1000 --report-rss -o "$out/scene" | tee "$out/log"
first=$(grep -m1 '^rss after frame' "$out/log" | awk '{print $(NF-1)}')
last=$(grep '^rss after frame' "$out/log" | tail -1 | awk '{print $(NF-1)}')
rows=$(($(wc -l < "$out/scene/telemetry.csv") - 1))
echo "soak: $frames frames in $(($(date +%s) - start)) s, telemetry rows $rows, RSS $first kB -> $last kB" \
    "(growth $((last - first)) kB, limit $max_growth_kb kB)"
[ "$rows" -eq "$frames" ] && [ $((last - first)) -le "$max_growth_kb" ]

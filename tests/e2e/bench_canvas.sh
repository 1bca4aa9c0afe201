#!/usr/bin/env bash
# `photopic bench --scene canvas` (issue 6): both shading paths, their tiles shaded and their times (timer query
# and glFinish wall clock, each labelled), after checking that the two outputs agree; the table also as JSON.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"

expect 0 "canvas bench at a small size" -- "$PHOTOPIC" bench --scene canvas --size 256x160 --frames 3 --warmup 1 \
    --set canvas.tileSize=32 --set canvas.occupancy=0.3 --json "$S/canvas.json"
echo "$OUTPUT" | sed 's/^/    /'
check "table lists the tiled path" grep -Eq '^tiled +[0-9]+/40 ' <<<"$OUTPUT"
check "table lists the full-screen path" grep -Eq '^fullscreen +40/40 ' <<<"$OUTPUT"
check "30% of the tiles shaded on the tiled path" grep -Eq '^tiled +12/40 +30\.0%' <<<"$OUTPUT"
check "the outputs were checked" contains "outputs agree"
check "timer-query column labelled" contains "gpu query ms"
check "wall-clock column labelled" contains "wall+finish ms"
check "JSON written" test -s "$S/canvas.json"
check "JSON has both paths" python3 -c "
import json, sys
d = json.load(open('$S/canvas.json'))
names = [p['name'] for p in d['paths']]
assert names == ['tiled', 'fullscreen'], names
assert all(p['medianWallMs'] > 0 and p['gpuSamples'] >= 1 for p in d['paths'])
assert d['paths'][0]['tilesShaded'] == 12 and d['paths'][1]['tilesShaded'] == 40
"
expect 2 "an unknown scene is bad input" -- "$PHOTOPIC" bench --scene nosuch --size 64x64 --frames 1
expect 2 "a post setting with --scene canvas is bad input" -- "$PHOTOPIC" bench --scene canvas --size 64x64 \
    --frames 1 --set bloom.enabled=false
check "it names the key" contains "bloom.enabled"
expect 2 "a bad canvas setting is bad input" -- "$PHOTOPIC" bench --scene canvas --size 64x64 --frames 1 \
    --set canvas.occupancy=2
check "it names the path" contains "canvas.occupancy"

expect 0 "pipeline bench --sync reports wall times" -- "$PHOTOPIC" bench --size 128x72 --frames 2 --sync \
    --json "$S/sync.json"
check "--sync prints the wall column" contains "wall ms"
check "--sync JSON has wall times" grep -q '"medianWallMs"' "$S/sync.json"

finish

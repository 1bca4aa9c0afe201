#!/usr/bin/env bash
# `photopic bench` lists every pass with its median GPU time, bytes and bandwidth, and writes JSON atomically;
# quality=legacy and --force-ldr runs produce images and say so.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"

ALL=(--set fxaa.enabled=true --set lensFlare.enabled=true --set vignette.enabled=true --set grain.enabled=true
     --set dazzle.enabled=true --set colorGrading.enabled=true)
expect 0 "bench at a small size with every effect" -- "$PHOTOPIC" bench --size 256x144 --frames 3 "${ALL[@]}" --json "$S/bench.json"
for pass in sanitize "bloom prefilter" "bloom down 1" "bloom up 0" "composite + grade + tonemap" fxaa \
            "lens flare prefilter" "lens flare features" "flare + dazzle + vignette + grain" total; do
    check "bench lists '$pass'" contains "$pass"
done
check "bench prints GB/s" contains "GB/s"
check "bench measures its copy reference on the frame" contains "bandwidth reference: rgba32f copy of the frame 256x144"
check "bench also copies a texture of one value" contains "of a texture of one value:"
check "bench prints the fraction of the copy" contains "of copy"
check "bench times the whole frame" contains "whole frame"
check "JSON written" test -s "$S/bench.json"
check "no temporary file left" test ! -e "$S/bench.json.tmp"
check "JSON has the passes" grep -q '"medianGpuMs"' "$S/bench.json"
check "JSON has each pass's fraction of the copy" grep -q '"fractionOfCopy"' "$S/bench.json"
check "JSON names the device and the driver" grep -q '"driver"' "$S/bench.json"
check "JSON has the copy reference" grep -q '"copyReference"' "$S/bench.json"
check "the reference copies the frame; the one-value copy is beside it, same format and bytes" python3 -c "import json,sys; \
d=json.load(open('$S/bench.json')); c=d['copyReference']; k=d['constantCopy']; \
sys.exit(0 if c['source'] == 'frame' and k['source'] == 'constant' and c['format'] == k['format'] == 'rgba32f' \
and c['bytesMoved'] == k['bytesMoved'] == 2 * 256 * 144 * 16 and c['medianMs'] > 0 and k['medianMs'] > 0 else 1)"
check "bench measures the reduction reference" contains "reduction reference: 2x2 box means of the frame"
check "the reduction reference reads the frame and writes a quarter of it in halves" python3 -c "import json,sys; \
r=json.load(open('$S/bench.json'))['reduceReference']; \
sys.exit(0 if r['format'] == 'rgba16f' and r['bytesMoved'] == 256 * 144 * 16 + 128 * 72 * 8 and r['medianMs'] > 0 \
else 1)"
check "JSON has the whole frame's time" grep -q '"frameMedianGpuMs"' "$S/bench.json"
expect 0 "bench of the default chain" -- "$PHOTOPIC" bench --size 64x64 --frames 2 --json "$S/default.json"
# Nothing is metered with auto exposure off: the metering line must not claim the image's bytes.
check "unmetered frame moves no metering bytes" python3 -c "import json,sys; d=json.load(open('$S/default.json')); \
m=[p for p in d['passes'] if p['name']=='metering']; sys.exit(0 if m and m[0]['bytesMoved']==0 else 1)"
check "bench reports the CPU's submission time" contains "ms to submit a frame"
check "JSON has the CPU's submission time" grep -q '"cpuSubmitMedianMs"' "$S/default.json"
check "bench names the bloom levels" contains "bloom levels 4"
check "JSON names the bloom levels" python3 -c "import json,sys; sys.exit(0 if json.load(open('$S/default.json'))['bloomLevels'] == 4 else 1)"
check "the input's format is named" python3 -c "import json,sys; d=json.load(open('$S/default.json')); \
sys.exit(0 if d['inputFormat'] == 'rgba32f' and d['copyReference']['format'] == 'rgba32f' else 1)"
# A half-float input: the copy reference takes its format, and the prefilter's bytes count half-float reads.
expect 0 "bench of a half-float input" -- "$PHOTOPIC" bench --size 64x64 --frames 2 --input-format rgba16f \
    --json "$S/half.json"
check "the half-float input is named in the table" contains "64x64 rgba16f input"
check "half-float input: an rgba16f copy, the prefilter reading 8 bytes a scene texel" python3 -c "import json,sys; \
d=json.load(open('$S/half.json')); f=json.load(open('$S/default.json')); \
p=lambda d: [x for x in d['passes'] if x['name']=='bloom prefilter'][0]['bytesMoved']; \
sys.exit(0 if d['inputFormat'] == 'rgba16f' and d['copyReference']['format'] == 'rgba16f' \
and p(f) - p(d) == 64 * 64 * 8 else 1)"
# A natural image: at its own size, or mirrored to --size (natural content at a benchmark's size).
expect 0 "bench of an image at its own size" -- "$PHOTOPIC" bench --input "$DATA/GoldenGate.exr" --frames 1 \
    --warmup 0 --json "$S/image.json"
check "the image is named in the table" contains "1262x860 rgba32f input ($DATA/GoldenGate.exr)"
check "the image at its own size in the JSON" python3 -c "import json,sys; d=json.load(open('$S/image.json')); \
sys.exit(0 if (d['width'], d['height']) == (1262, 860) and d['input'].endswith('GoldenGate.exr') \
and not d['inputMirrored'] else 1)"
expect 0 "bench of an image mirrored to a size" -- "$PHOTOPIC" bench --input "$DATA/GoldenGate.exr" --size 2600x200 \
    --frames 1 --warmup 0 --json "$S/mirrored.json"
check "the mirroring is named in the table" contains "2600x200 rgba32f input ($DATA/GoldenGate.exr, mirrored to this size)"
check "the mirrored image's size in the JSON" python3 -c "import json,sys; d=json.load(open('$S/mirrored.json')); \
sys.exit(0 if (d['width'], d['height']) == (2600, 200) and d['inputMirrored'] else 1)"
check "the synthetic frame is named as such" python3 -c "import json,sys; \
sys.exit(0 if json.load(open('$S/default.json'))['input'] == 'synthetic' else 1)"
expect 2 "a bad size with an image is bad input" -- "$PHOTOPIC" bench --input "$DATA/GoldenGate.exr" --size 2x2
check "the size is named" contains "size '2x2'"
expect 2 "an input format the bench does not make is refused" -- "$PHOTOPIC" bench --size 64x64 --input-format rgb9e5
# A renderer's EXR at its own size brings its own 3D layers: Cycles' depth, normals and motion of the committed
# Blender render, its camera from the exported track.
BLENDER="$(cd "$(dirname "$0")/../data/blender" && pwd)"
expect 0 "bench on a Cycles frame's own 3D layers" -- "$PHOTOPIC" bench --input "$BLENDER/passes/frame_0003.exr" \
    --camera "$BLENDER/track.json" --frames 1 --warmup 0 --set ssao.enabled=true --set contactShadows.enabled=true \
    --json "$S/cycles.json"
check "the file's layers are named" contains "3D inputs: the file's (depth, normals, motion, camera, sun)"
check "the JSON says the 3D inputs are the file's, at its size, and GTAO ran on them" python3 -c "import json,sys; \
d=json.load(open('$S/cycles.json')); n=[p['name'] for p in d['passes']]; \
sys.exit(0 if d['inputs3d'] == 'file' and (d['width'], d['height']) == (320, 180) and 'gtao' in n \
and 'contact shadows' in n else 1)"
check "the synthetic frame says so" python3 -c "import json,sys; \
sys.exit(0 if json.load(open('$S/default.json'))['inputs3d'] == 'synthetic' else 1)"
expect 2 "--camera with a colour mirrored to --size is refused" -- "$PHOTOPIC" bench \
    --input "$BLENDER/passes/frame_0003.exr" --camera "$BLENDER/track.json" --size 640x360 --frames 1
check "the refusal names --camera" contains "bench --camera"
expect 2 "--floor on a frame with its own 3D layers is refused" -- "$PHOTOPIC" bench \
    --input "$BLENDER/passes/frame_0003.exr" --camera "$BLENDER/track.json" --floor --frames 1
check "the refusal names the file" contains "frame_0003.exr brings its own depth, normals and camera"
# --queue-ahead: untimed busy work before each timed frame and reference (the frames, both copies, the
# reduction, the whole frame); the report says on how many the GPU was still on it when the frame had been
# submitted (none on llvmpipe, which runs a dispatch when it is issued).
expect 0 "bench with the queue kept ahead" -- "$PHOTOPIC" bench --size 64x64 --frames 3 --warmup 1 --queue-ahead \
    --json "$S/ahead.json"
check "bench says how long the busy work ran and where it held" contains "of untimed GPU work before each timed frame"
check "bench also times the frame as submitted to an idle GPU" contains "whole frame, as submitted"
check "JSON has the busy work and the frames it held on" python3 -c "import json,sys; q=json.load(open('$S/ahead.json'))['queueAhead']; \
sys.exit(0 if q['busyMs'] >= 0.5 and q['framesTimed'] == 3 + 3 + 3 + 3 + 3 and 0 <= q['framesHeld'] <= q['framesTimed'] \
and q['frameAsSubmittedMedianGpuMs'] > 0 else 1)"
expect 2 "--queue-ahead and --sync exclude each other" -- "$PHOTOPIC" bench --size 64x64 --queue-ahead --sync
expect 2 "--queue-ahead does not time the canvas scene" -- "$PHOTOPIC" bench --scene canvas --queue-ahead
expect 2 "bad size is bad input" -- "$PHOTOPIC" bench --size 12by3
expect 0 "bench on the legacy tier" -- "$PHOTOPIC" bench --size 64x64 --frames 2 --set quality=legacy
check "legacy bench reports the LDR path" contains "LDR"

expect 0 "legacy image" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/legacy.png" --set quality=legacy
check "legacy PNG written" test -s "$S/legacy.png"
check "legacy warns" contains "LDR"
expect 0 "forced-LDR image with every effect" -- "$PHOTOPIC" image "$DATA/Desk.exr" -o "$S/ldr.png" --force-ldr "${ALL[@]}"
check "forced-LDR PNG written" test -s "$S/ldr.png"
check "forced LDR warns" contains "LDR"
expect 0 "info reports the legacy tier" -- "$PHOTOPIC" info --set quality=legacy
check "info says legacy runs LDR" contains "legacy -> LDR"
expect 0 "threshold bloom to EXR" -- "$PHOTOPIC" image "$DATA/Desk.hdr" -o "$S/bloom.exr" --set bloom.mode=threshold --set bloom.intensity=0.5
check "EXR written" test -s "$S/bloom.exr"
expect 0 "settings --defaults" -- "$PHOTOPIC" settings --defaults
for key in bloom colorGrading fxaa lensFlare vignette grain dazzle quality; do
    check "defaults list $key" contains "\"$key\""
done

finish

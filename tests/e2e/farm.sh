#!/usr/bin/env bash
# A render farm of one node: a single-node Slurm cluster on localhost (munged, slurmctld, slurmd, state in the
# scratch folder) runs the job set photopic farm writes for a 48-frame sequence in 4 chunks (a meter array, the
# plan after it, a render array after that) and every frame is compared with a single run. Without TAA the
# chunks are the single run's bytes; with TAA and the default preroll, every frame within the residual
# docs/farm.md measures. Needs root and Debian's slurm-wlm and munge (scripts/deps.sh).
source "$(dirname "$0")/lib.bash"
# shellcheck source=tests/e2e/slurm-cluster.bash
source "$(dirname "$0")/slurm-cluster.bash"
S="$SCRATCH"
FIX="${PHOTOPIC_FARM_FIXTURE:?built by CMake}"
PHOTOPIC=$(realpath "$PHOTOPIC")
trap slurm_cluster_stop EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

expect 0 "a 48-frame testbed sequence" -- "$PHOTOPIC" scene testbed -o "$S/tb" --frames 48 --size 96x54
IN="$S/tb/scene_%04d.exr"
# The testbed's shot changes at frame 36 (its telemetry's cut column): declared, as a TD declares a shot's cuts.
CUTS=()
for cut in $(awk -F, 'NR > 1 && $4 == 1 { print $1 }' "$S/tb/telemetry.csv"); do
    CUTS+=(--cut "$cut")
done
check "the testbed's cut is found" test "${CUTS[*]}" = "--cut 36"
check "a single-node Slurm cluster starts" slurm_cluster_start "$S/cluster" || { finish; exit 1; }

# submit NAME FARM-OPTIONS...: photopic farm --submit for the sequence; waits for its three jobs.
submit() {
    local name="$1"
    shift
    expect 0 "photopic farm $name: 4 chunks submitted" -- "$PHOTOPIC" farm "$IN" --jobs "$S/$name" --chunk 12 \
        --fps 24 "${CUTS[@]}" --set autoExposure.enabled=true -o "$S/$name/out/f%04d.png" --submit "$@" ||
        return 1
    check "prints the chunking" contains "in 4 chunk(s) of 12"
    local ids
    ids=$(tail -1 <<< "$OUTPUT")
    # shellcheck disable=SC2086 # three job ids
    check "the meter array, the plan and the render array end COMPLETED ($ids)" slurm_wait_jobs -t 240 $ids
}

# Without TAA: the farm's frames are the single run's bytes with the farm's own exposure track.
submit plain
check "the render array wrote every frame" test "$(ls "$S"/plain/out/*.png 2> /dev/null | wc -l)" -eq 48
check "each stage's tasks logged" test "$(ls "$S"/plain/logs/{meter,render}-*.log | wc -l)" -eq 8
expect 0 "meter the whole sequence on this machine" -- "$PHOTOPIC" meter "$IN" --settings "$S/plain/settings.json" \
    --fps 24 -o "$S/meter-all.csv"
check "the chunks' meter files hold the whole run's rows" bash -c \
    'diff <(tail -n +3 "$1") <(for i in 0 1 2 3; do tail -n +3 "$2/chunk-$i.csv"; done)' _ "$S/meter-all.csv" \
    "$S/plain/meter"
expect 0 "plan from the whole run's metering" -- "$PHOTOPIC" expose "$S/meter-all.csv" \
    --settings "$S/plain/settings.json" --fps 24 "${CUTS[@]}" -o "$S/exposure-all.csv"
check "the farm's plan is the whole run's" cmp -s "$S/exposure-all.csv" "$S/plain/exposure.csv"
expect 0 "the single run with the farm's track" -- "$PHOTOPIC" image "$IN" --settings "$S/plain/settings.json" \
    --fps 24 --exposure-track "$S/plain/exposure.csv" -o "$S/single/f%04d.png"
check "every frame the single run's bytes" bash -c \
    'for f in "$1"/*.png; do cmp -s "$f" "$2/$(basename "$f")" || { echo "differs: $f"; exit 1; }; done' _ \
    "$S/single" "$S/plain/out"

# With TAA, jitter and the default preroll: within the measured residual (docs/farm.md).
submit taa --set aa.mode=taa --image-option=--jitter --image-option=halton
check "the default preroll is in the render jobs" grep -q -- "--preroll 24" "$S/taa/render.sbatch"
expect 0 "the single TAA run with the farm's track" -- "$PHOTOPIC" image "$IN" --settings "$S/taa/settings.json" \
    --fps 24 --jitter halton --exposure-track "$S/taa/exposure.csv" -o "$S/single-taa/f%04d.png"
expect 0 "compare the TAA farm with the single run" -- "$FIX" "$S/single-taa" "$S/taa/out"
grep -E "f00(12|24|36)|^all" <<< "$OUTPUT"
check "48 frames compared" test "$(grep -c '^frame' <<< "$OUTPUT")" -eq 48
check "every frame within 0.5 code values mean, at most 2% of its pixels more than 2 off" \
    awk '$1 == "frame" { n++; if ($4 > 0.5 || $8 > 0.02) bad++ } END { exit !(n == 48 && !bad) }' <<< "$OUTPUT"

# A job set for a sequence with a gap, or without auto exposure, is refused before anything is written.
expect 2 "farm without auto exposure" -- "$PHOTOPIC" farm "$IN" --jobs "$S/bad" -o "$S/bad/f%04d.png"
check "names the key" contains "autoExposure.enabled"
expect 2 "farm to a single output file" -- "$PHOTOPIC" farm "$IN" --jobs "$S/bad" -o "$S/bad/out.png" \
    --set autoExposure.enabled=true
check "says it needs a pattern" contains "frame-numbered output pattern"
check "nothing written by the failures" test ! -e "$S/bad"

read -r -a daemons <<< "$(cat "$S/cluster/munge/munged.pid" "$S/cluster/slurmctld.pid" "$S/cluster/slurmd.pid" |
    tr '\n' ' ')"
slurm_cluster_stop
none_alive() { # (a zombie counts as gone: pid 1 of a container may never reap it)
    local pid
    for pid; do ! _slurm_alive "$pid" || return 1; done
}
check "the cluster's three daemons are gone (${daemons[*]})" test "${#daemons[@]}" -eq 3
check "none of them alive" none_alive "${daemons[@]}"
finish

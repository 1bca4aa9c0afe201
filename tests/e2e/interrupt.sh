#!/usr/bin/env bash
# What a failed or interrupted run leaves: the outputs exactly as they were before it. A second run over the
# same outputs that fails part way puts back every file it had replaced; SIGTERM or SIGINT at any frame
# ends the run with 143 or 130, no temporary file, and the outputs as before, so a rerun gives what an
# uninterrupted run gives.
source "$(dirname "$0")/lib.bash"
cd "$SCRATCH"

leftovers() { find . \( -name '.*.tmp-*' -o -name '.*.previous-*' \) -print; }
no_leftovers() { [ -z "$(leftovers)" ]; }
same_dir() { diff -r "$1" "$2" > /dev/null; }

# --- a failed run over existing outputs
expect 0 "make 12 frames" -- "$PHOTOPIC" scene tabletop --format exr --size 64x36 --frames 12 -o src
expect 0 "first run" -- "$PHOTOPIC" image src/*.exr -o res/f%04d.png --telemetry res.csv \
    --set autoExposure.enabled=true
cp -r res first && cp res.csv first.csv
cp src/frame_0007.exr frame_0007.good
head -c 2000 frame_0007.good > src/frame_0007.exr
expect 2 "a second run with frame 7 truncated" -- "$PHOTOPIC" image src/*.exr -o res/f%04d.png \
    --telemetry res.csv --tonemap agx --frames-in-flight 3
check "names the frame" contains "frame_0007.exr"
check "every frame of the first run is back, byte for byte" same_dir first res
check "the first run's telemetry is back" cmp -s first.csv res.csv
check "no temporary or set-aside file" no_leftovers
cp frame_0007.good src/frame_0007.exr

expect 0 "a second run that succeeds replaces them" -- "$PHOTOPIC" image src/*.exr -o res/f%04d.png \
    --telemetry res.csv --tonemap agx
check "the frames changed" test "$(cmp -s first/f0003.png res/f0003.png; echo $?)" = 1
check "no set-aside copies kept" no_leftovers

# --- signals at any frame of a 60-frame sequence
expect 0 "make 60 frames" -- "$PHOTOPIC" scene tabletop --format exr --size 64x36 --frames 60 -o seq
AE=(--set autoExposure.enabled=true --tonemap aces-fitted)
expect 0 "uninterrupted run" -- "$PHOTOPIC" image seq/*.exr -o whole/f%04d.png --telemetry whole.csv "${AE[@]}"

# count_written DIR: frames this run has put in place so far: new files the first time, set-aside copies
# (each replaced frame leaves one while the run lasts) when DIR held a whole run already.
count_written() {
    if [ "$2" = fresh ]; then
        find "$1" -maxdepth 1 -name 'f*.png' 2> /dev/null | wc -l
    else
        find "$1" -maxdepth 1 -name '.*.previous-*' 2> /dev/null | wc -l
    fi
}

# wait_for PID COUNT N: until the command COUNT prints at least N (at most 15 s), or PID has ended.
wait_for() {
    local pid="$1" count="$2" n="$3"
    for _ in $(seq 3000); do
        [ "$($count)" -ge "$n" ] && return
        kill -0 "$pid" 2> /dev/null || return
        sleep 0.005
    done
}

# interrupt SIGNAL AT STATE: starts the run into cut/, sends SIGNAL once AT frames are in place, and checks
# the exit status, the leftovers and that cut/ is as before (absent when STATE is fresh, else whole/).
interrupt() {
    local signal="$1" at="$2" state="$3"
    # Started with SIGINT at its default: a script's background job would otherwise ignore it (and photopic
    # keeps a signal ignored that it was started with, as nohup relies on).
    python3 -c 'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execv(sys.argv[1], sys.argv[1:])' \
        "$PHOTOPIC" image seq/*.exr -o cut/f%04d.png --telemetry cut.csv "${AE[@]}" -q > run.log 2>&1 &
    local pid=$!
    wait_for "$pid" "count_written cut $state" "$at"
    kill "-$signal" "$pid" 2> /dev/null
    wait "$pid"
    local status=$?
    local want=143
    [ "$signal" = INT ] && want=130
    if [ "$status" = 0 ] || { [ "$status" = "$want" ] && ! grep -q "interrupted by" run.log; }; then
        # The run had committed its outputs when the signal came (exit 0), or was ending (the handlers
        # were gone, the default action ended the process): its outputs are whole.
        echo "note: the run finished before SIG$signal at frame $at took effect (exit $status)"
        check "SIG$signal after the end: the whole run" same_dir whole cut
        check "SIG$signal after the end: the whole telemetry" cmp -s whole.csv cut.csv
    else
        interrupted=$((interrupted + 1))
        check "SIG$signal at frame $at ($state): exit $want" test "$status" = "$want"
        check "SIG$signal at frame $at ($state): said so" grep -q "interrupted by SIG$signal" run.log
        if [ "$state" = fresh ]; then
            check "SIG$signal at frame $at ($state): no frame, no folder left" test ! -e cut
            check "SIG$signal at frame $at ($state): no telemetry left" test ! -e cut.csv
        else
            check "SIG$signal at frame $at ($state): every frame as before" same_dir whole cut
            check "SIG$signal at frame $at ($state): the telemetry as before" cmp -s whole.csv cut.csv
        fi
    fi
    check "SIG$signal at frame $at ($state): no temporary or set-aside file" no_leftovers
}

interrupted=0
for at in 1 13 30 47; do
    rm -rf cut cut.csv
    interrupt TERM "$at" fresh
    expect 0 "rerun after SIGTERM at frame $at" -- "$PHOTOPIC" image seq/*.exr -o cut/f%04d.png \
        --telemetry cut.csv "${AE[@]}"
    check "rerun after SIGTERM at frame $at: the uninterrupted run's frames" same_dir whole cut
    check "rerun after SIGTERM at frame $at: the uninterrupted run's telemetry" cmp -s whole.csv cut.csv
done
# Over a whole earlier run: what was replaced comes back.
for at in 5 40; do
    interrupt TERM "$at" replacing
done
rm -rf cut cut.csv
interrupt INT 20 fresh
# A signal can come after a run has committed; most of these must land inside the run.
check "at least 4 of the 7 signals interrupted a run ($interrupted did)" test "$interrupted" -ge 4

# A signal the run was started with ignored stays ignored (nohup): the run completes.
rm -rf cut cut.csv
nohup "$PHOTOPIC" image seq/*.exr -o cut/f%04d.png --telemetry cut.csv "${AE[@]}" -q > run.log 2>&1 &
pid=$!
wait_for "$pid" "count_written cut fresh" 5
kill -HUP "$pid"
wait "$pid"
check "SIGHUP under nohup: the run completes (exit 0)" test $? = 0
check "SIGHUP under nohup: the whole run" same_dir whole cut

# --- the scenes' own runs
"$PHOTOPIC" scene tabletop --frames 400 --size 64x36 -o scenecut -q > run.log 2>&1 &
pid=$!
scene_frames() { find scenecut -maxdepth 1 -name 'frame_*' 2> /dev/null | wc -l; }
wait_for "$pid" scene_frames 10
kill -TERM "$pid"
wait "$pid"
check "scene: SIGTERM part way exits 143" test $? = 143
check "scene: nothing left" test ! -e scenecut
check "scene: no temporary file" no_leftovers
finish

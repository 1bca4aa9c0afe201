#!/usr/bin/env bash
# Instructions per frame of `photopic bench` under callgrind: a deterministic measure for work on a software
# renderer (llvmpipe runs the shaders on the CPU), where wall times on a shared machine vary by 2x between
# runs. The count is that of a 12-frame run minus that of a 2-frame run, divided by 10, after a 1-frame run that
# fills Mesa's shader cache, so start-up and shader compilation drop out; it covers both of the bench's loops
# (per pass and whole frame) and its copy reference, the same work for any two builds being compared.
# Usage: scripts/bench-instructions.sh PHOTOPIC [bench options...]   (default size 480x270; an --input at its own)
# Needs valgrind (Debian package valgrind); about a minute per build at the default size.
set -euo pipefail
if [ $# -lt 1 ]; then
    echo "usage: $0 PHOTOPIC [bench options...]" >&2
    exit 2
fi
bin="$1"
shift
if ! command -v valgrind > /dev/null; then
    echo "$0: valgrind is not installed (apt-get install valgrind)" >&2
    exit 2
fi
args=("$@")
if [[ " $* " != *" --size "* && " $* " != *" --size="* && " $* " != *" --input "* ]]; then
    args=(--size 480x270 "$@")
fi
count() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null --smc-check=all-non-file \
        "$bin" bench "${args[@]}" --frames "$1" --warmup 0 2>&1 | awk '/Collected :/ {print $4}'
}
count 1 > /dev/null
a=$(count 2)
b=$(count 12)
if [ -z "$a" ] || [ -z "$b" ]; then
    echo "$0: callgrind gave no count (does '$bin bench ${args[*]}' run?)" >&2
    exit 1
fi
awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f million instructions per frame\n", (b - a) / 10 / 1e6 }'

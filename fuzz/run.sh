#!/usr/bin/env bash
# Runs each libFuzzer harness for FUZZ_SECONDS (default 60) on one core, starting from the committed corpus;
# FUZZ_PARALLEL (default 1) harnesses at a time, so 9 targets on two cores take half the wall time.
# FUZZ_TIMEOUT (default 10) is the seconds one input may take, wall clock: raise it when the harnesses share
# the cores with other work at a lower priority (nice), where an input can wait longer than it runs.
# Usage: fuzz/run.sh BUILD_DIR TARGET...   (`make fuzz` builds BUILD_DIR first and passes every target.)
# New inputs go to BUILD_DIR/corpus/<target> (the committed fuzz/corpus/<target> is only read); a crash,
# leak or timeout leaves its input in BUILD_DIR/artifacts/<target>/ and makes the script fail. Per target
# it prints the executions, the largest input libFuzzer may make and the final coverage (libFuzzer's cov:
# edges, ft: features).
set -uo pipefail
build="$1"
shift
seconds="${FUZZ_SECONDS:-60}"
parallel="${FUZZ_PARALLEL:-1}"
timeout="${FUZZ_TIMEOUT:-10}"
if ! [[ "$parallel" =~ ^[1-9][0-9]*$ ]]; then
    echo "FUZZ_PARALLEL must be a positive number of harnesses, not '$parallel'" >&2
    exit 2
fi
here="$(cd "$(dirname "$0")" && pwd)"

# The longest input libFuzzer may make, where its own default is not enough: left to itself it takes the
# largest committed input (a few KB at most), so a settings file or an override list far past that -- deep
# nesting, a long line -- is never tried. Those readers take whole user files: 1 MB, and -len_control=0 so
# long inputs are tried from the start rather than after hours of slowly raising the bound.
length_flags() {
    case "$1" in
        settings | override) echo "-max_len=1048576 -len_control=0 " ;;
        *) ;;
    esac
}

run_target() {
    local target="$1"
    local corpus="$build/corpus/$target"
    local artifacts="$build/artifacts/$target"
    local log="$build/fuzz-$target.log"
    mkdir -p "$corpus" "$artifacts"
    # -rss_limit_mb: the readers' own limits keep a case far below this.
    # shellcheck disable=SC2046  # the length flags are separate words
    "$build/fuzz/photopic_fuzz_$target" "$corpus" "$here/corpus/$target" \
        -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 -print_final_stats=1 \
        $(length_flags "$target") -artifact_prefix="$artifacts/" > "$log" 2>&1
    echo $? > "$build/fuzz-$target.status"
}

for target in "$@"; do
    rm -f "$build/fuzz-$target.status"
    while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do
        wait -n
    done
    echo "== fuzz $target for ${seconds}s $(length_flags "$target")(log: $build/fuzz-$target.log)"
    run_target "$target" &
done
wait

failed=()
summary=()
for target in "$@"; do
    log="$build/fuzz-$target.log"
    status=$(cat "$build/fuzz-$target.status" 2> /dev/null || echo "?")
    last=$(grep -E '^#[0-9]+' "$log" | tail -1)
    runs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}')
    # The bound given here, else the one libFuzzer chose and printed.
    max_len=$(length_flags "$target" | grep -oE -- '-max_len=[0-9]+' | grep -oE '[0-9]+')
    if [ -z "$max_len" ]; then
        max_len=$(grep -oE 'will not generate inputs larger than [0-9]+' "$log" | grep -oE '[0-9]+$' |
            head -1)
    fi
    summary+=("$(printf '%-9s execs %-10s max_len %-8s %s' "$target" "${runs:-?}" "${max_len:-?}" \
        "$(echo "$last" | grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[0-9]+[a-zA-Z]*')")")
    if [ "$status" != 0 ]; then
        failed+=("$target")
        echo "== $target failed (exit $status; log: $log)"
        grep -E 'ERROR|SUMMARY|==[0-9]+==|promise broken' "$log" | head -5
    fi
done
echo "== fuzz summary (${seconds}s per target, ${parallel} at a time)"
printf '%s\n' "${summary[@]}"
if [ ${#failed[@]} -ne 0 ]; then
    echo "FAILED: ${failed[*]} (inputs in $build/artifacts/)"
    exit 1
fi

#!/usr/bin/env bash
# Runs each libFuzzer harness for FUZZ_SECONDS (default 60) on one core, starting from the committed corpus.
# Usage: fuzz/run.sh BUILD_DIR TARGET...   (`make fuzz` builds BUILD_DIR first and passes every target.)
# New inputs go to BUILD_DIR/corpus/<target> (the committed fuzz/corpus/<target> is only read); a crash,
# leak or timeout leaves its input in BUILD_DIR/artifacts/<target>/ and makes the script fail. Per target
# it prints the executions and the final coverage (libFuzzer's cov: edges, ft: features).
set -uo pipefail
build="$1"
shift
seconds="${FUZZ_SECONDS:-60}"
here="$(cd "$(dirname "$0")" && pwd)"
failed=()
summary=()
for target in "$@"; do
    corpus="$build/corpus/$target"
    artifacts="$build/artifacts/$target"
    mkdir -p "$corpus" "$artifacts"
    log="$build/fuzz-$target.log"
    echo "== fuzz $target for ${seconds}s (log: $log)"
    # -rss_limit_mb: the readers' own limits keep a case far below this; -timeout: seconds per input.
    "$build/fuzz/photopic_fuzz_$target" "$corpus" "$here/corpus/$target" \
        -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$artifacts/" > "$log" 2>&1
    status=$?
    last=$(grep -E '^#[0-9]+' "$log" | tail -1)
    runs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}')
    summary+=("$(printf '%-9s execs %-10s %s' "$target" "${runs:-?}" "$(echo "$last" | grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[0-9]+[a-zA-Z]*')")")
    if [ $status -ne 0 ]; then
        failed+=("$target")
        grep -E 'ERROR|SUMMARY|==[0-9]+==' "$log" | head -5
    fi
done
echo "== fuzz summary (${seconds}s per target)"
printf '%s\n' "${summary[@]}"
if [ ${#failed[@]} -ne 0 ]; then
    echo "FAILED: ${failed[*]} (inputs in $build/artifacts/)"
    exit 1
fi

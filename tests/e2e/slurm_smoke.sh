#!/usr/bin/env bash
# Smoke test of tests/e2e/slurm-cluster.bash: a real single-node Slurm cluster on localhost runs a 3-task job array
# (several tasks at once when there are CPUs for it) and a job that depends on it and checks its files;
# slurm_wait_jobs reports success for them and failure for a job that exits 3, whose afterok dependant is
# cancelled rather than left pending; and nothing of the cluster is left running afterwards. Needs root and the
# packages slurm-wlm and munge (scripts/deps.sh). Takes no arguments (those an e2e runner passes are ignored).
# Prints how long the start, the jobs and the stop took. Set SLURM_SMOKE_KEEP=1 to keep the cluster's folder.
set -euo pipefail
# shellcheck source=tests/e2e/slurm-cluster.bash
source "$(dirname "$0")/slurm-cluster.bash"

conf_before=${SLURM_CONF-unset}
dir=$(mktemp -d "${TMPDIR:-/tmp}/slurm-smoke.XXXXXX")
cleanup() {
    local status=$?
    slurm_cluster_stop
    if [ "${SLURM_SMOKE_KEEP:-0}" = 1 ]; then
        echo "kept $dir"
    else
        rm -rf "$dir"
    fi
    [ "$status" -eq 0 ] && echo "slurm smoke: ok" || echo "slurm smoke: FAILED (exit $status)"
}
trap cleanup EXIT
# Killed (a runner's timeout, ^C): exit through the EXIT trap with the signal's status, which it then reports.
trap 'exit 130' INT
trap 'exit 143' TERM

fail() {
    echo "FAIL: $*" >&2
    exit 1
}
ms() { date +%s%3N; }
since() { echo "$(($(ms) - $1)) ms"; }

t0=$(ms)
slurm_cluster_start "$dir/cluster" || fail "the cluster did not start"
echo "cluster started in $(since "$t0"): node $SLURM_CLUSTER_NODE, $(sinfo -h -o '%c CPUs, %m MB') "

# Jobs write under out/; their own output goes to logs/. --chdir, so nothing lands in the caller's folder.
out="$dir/out"
mkdir -p "$out" "$dir/logs"
submit() { sbatch --parsable --chdir="$dir" --output="$dir/logs/%x-%A_%a.out" --cpus-per-task=1 "$@"; }

t1=$(ms)
# Each task notes when it started and ended, to see that tasks ran side by side (CR_Core, not whole nodes).
array=$(submit --job-name=array --array=0-2 --wrap "
    start=\$(date +%s%N); sleep 2
    echo \"task \$SLURM_ARRAY_TASK_ID on \$(hostname -s) \$start \$(date +%s%N)\" > '$out/part-'\$SLURM_ARRAY_TASK_ID")
check=$(submit --job-name=check --dependency="afterok:$array" --wrap "
    for i in 0 1 2; do grep -q \"^task \$i \" '$out/part-'\$i || { echo \"part \$i missing or wrong\"; exit 1; }; done
    cat '$out'/part-* > '$out/all' && echo checked > '$out/checked'")
echo "submitted array job $array and dependent job $check"
slurm_wait_jobs -t 120 "$array" "$check" || fail "the array or its dependent job did not complete"
echo "array and dependent job done in $(since "$t1")"

[ "$(cat "$out/checked" 2> /dev/null)" = checked ] || fail "the dependent job left no out/checked"
[ "$(wc -l < "$out/all")" -eq 3 ] || fail "out/all should have 3 lines: $(cat "$out/all")"
# Tasks overlap if one started before another ended; with one CPU they cannot.
overlap=$(awk '{ s[NR] = $5; e[NR] = $6 } END { for (i in s) for (j in s) if (i != j && s[i] < s[j] && s[j] < e[i]) { print "yes"; exit } }' "$out/all")
if [ "$(nproc)" -gt 1 ]; then
    [ "$overlap" = yes ] || fail "no two array tasks ran at the same time on $(nproc) CPUs: $(cat "$out/all")"
    echo "array tasks ran side by side"
fi

# A failing job must be reported as such, and its afterok dependant cancelled (kill_invalid_depend), not pending.
t2=$(ms)
failing=$(submit --job-name=failing --wrap 'echo about to fail; exit 3')
orphan=$(submit --job-name=orphan --dependency="afterok:$failing" --wrap 'true')
if slurm_wait_jobs -t 60 "$failing" "$orphan" 2> "$dir/wait-bad.log"; then
    fail "slurm_wait_jobs returned 0 for a job that exits 3"
fi
grep -q "FAILED" "$dir/wait-bad.log" || fail "the failed job is not reported FAILED: $(cat "$dir/wait-bad.log")"
grep -q "exit code 3:0" "$dir/wait-bad.log" || fail "exit code 3 not reported: $(cat "$dir/wait-bad.log")"
grep -q "CANCELLED" "$dir/wait-bad.log" || fail "the dependant is not CANCELLED: $(cat "$dir/wait-bad.log")"
echo "failing job reported, its dependant cancelled, in $(since "$t2")"

# Stopping leaves none of the cluster's processes and is idempotent.
pids=$(cat "$dir/cluster/munge/munged.pid" "$dir/cluster/slurmctld.pid" "$dir/cluster/slurmd.pid")
t3=$(ms)
slurm_cluster_stop
slurm_cluster_stop
echo "cluster stopped in $(since "$t3")"
for pid in $pids; do
    ! _slurm_alive "$pid" || fail "pid $pid of the cluster still runs after slurm_cluster_stop"
done
[ "${SLURM_CONF-unset}" = "$conf_before" ] || fail "SLURM_CONF not restored by the stop: ${SLURM_CONF-unset}"
echo "total $(since "$t0")"

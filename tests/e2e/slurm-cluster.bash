# shellcheck shell=bash
# A throwaway single-node Slurm cluster on localhost, for end-to-end tests of the render farm. Source it:
#
#     source tests/e2e/slurm-cluster.bash
#     trap slurm_cluster_stop EXIT             # the daemons go even when the test fails
#     slurm_cluster_start "$(mktemp -d)"       # munged, slurmctld, slurmd; exports SLURM_CONF for sbatch & co.
#     id=$(sbatch --parsable --wrap 'true')
#     slurm_wait_jobs -t 120 "$id"             # non-zero unless every job (every array task) ended COMPLETED
#     slurm_cluster_stop                       # idempotent
#
# Everything the daemons read or write (munge key and socket, slurm.conf, pid files, logs, state, spool) is under
# the caller's DIR, and they are stopped by the pids they were started with, never by name, so a real munge or
# Slurm on the same machine is left alone. The EXIT trap also runs when the test is killed by SIGTERM or SIGINT;
# if it is killed by SIGKILL, a watchdog stops the cluster within a second or two. Every wait is bounded. The functions return non-zero on failure and
# never exit the caller's shell; they are written for callers under set -euo pipefail.
#
# Needs root (slurmd must be root to start jobs; munged and slurmctld run as root too, so that DIR can be a
# root-only mktemp folder no munge or slurm user could read) and the Debian packages slurm-wlm and munge
# (scripts/deps.sh). It needs neither systemd nor cgroups: proctrack/linuxproc and task/none.
#
# Named .bash, like lib.bash, so that the tests/e2e/*.sh glob does not make it a test of its own.

# Set while a cluster runs: its folder, its one node (this host's short name) and its one partition. Sourcing
# the file again keeps the state of a cluster already started (its pids are needed to stop it).
if [ -z "${_SLURM_CLUSTER_LOADED:-}" ]; then
    _SLURM_CLUSTER_LOADED=1
    SLURM_CLUSTER_DIR=""
    SLURM_CLUSTER_NODE=""
    _slurm_pids=()          # "name:pid" of the daemons started, in start order
    _slurm_watchdog=""      # pid of the subshell that stops the cluster if its caller dies without doing so
    _slurm_old_conf=""      # the caller's SLURM_CONF, restored by slurm_cluster_stop
    _slurm_old_conf_set=0   # 1: it was set, 2: it was not, 0: not saved yet
fi
SLURM_CLUSTER_PARTITION="photopic"

# Every daemon is started with this variable set to DIR in its environment. slurmstepd (forked and exec'd by
# slurmd, then reparented to init) inherits it, so slurm_cluster_stop can find stray step daemons of this
# cluster, and only of this cluster, without going by name; it also guards the recorded pids against reuse.
_SLURM_MARK="PHOTOPIC_SLURM_CLUSTER"

_slurm_log() { echo "slurm-cluster: $*" >&2; }

# _slurm_alive PID: the process exists and is not a zombie (pid 1 of a container may never reap the daemons).
_slurm_alive() {
    local stat
    { read -r stat < "/proc/$1/stat"; } 2> /dev/null || return 1
    stat=${stat##*) }
    [ "${stat%% *}" != Z ]
}

# _slurm_ours PID: alive and started by this cluster (its environment carries the mark with this DIR).
_slurm_ours() {
    _slurm_alive "$1" && grep -qzxF -- "$_SLURM_MARK=$SLURM_CLUSTER_DIR" "/proc/$1/environ" 2> /dev/null
}

# _slurm_marked: pids of every live process carrying this cluster's mark (daemons and slurmstepd), one grep.
_slurm_marked() {
    local f pid
    for f in $(grep -lzxF -- "$_SLURM_MARK=$SLURM_CLUSTER_DIR" /proc/[0-9]*/environ 2> /dev/null || true); do
        pid=${f#/proc/}
        pid=${pid%/environ}
        _slurm_alive "$pid" && echo "$pid"
    done
    return 0
}

# _slurm_with_descendants PID...: the pids and all their live descendants (job tasks under a slurmstepd, the
# sleep under the watchdog), read from /proc so that it needs no procps.
_slurm_with_descendants() {
    local -A children=()
    local f line rest pid ppid
    for f in /proc/[0-9]*/stat; do
        { read -r line < "$f"; } 2> /dev/null || continue
        pid=${f#/proc/}
        pid=${pid%/stat}
        rest=${line##*) }         # after the command name, which may hold spaces: "STATE PPID ..."
        rest=${rest#* }
        ppid=${rest%% *}
        children[$ppid]+=" $pid"
    done
    local -a queue=("$@")
    local -A seen=()
    while [ ${#queue[@]} -gt 0 ]; do
        pid=${queue[0]}
        queue=("${queue[@]:1}")
        [ -n "${seen[$pid]:-}" ] && continue
        seen[$pid]=1
        _slurm_alive "$pid" && echo "$pid"
        # shellcheck disable=SC2206 # the list is pids separated by spaces
        queue+=(${children[$pid]:-})
    done
}

# _slurm_terminate TIMEOUT_S PID...: TERM, wait up to TIMEOUT_S for them to go, then KILL what is left.
_slurm_terminate() {
    local timeout=$1 pid deadline
    shift
    [ $# -gt 0 ] || return 0
    kill -TERM "$@" 2> /dev/null || true
    deadline=$((SECONDS + timeout))
    while [ "$SECONDS" -lt "$deadline" ]; do
        local left=0
        for pid; do _slurm_alive "$pid" && left=1; done
        [ "$left" -eq 0 ] && return 0
        sleep 0.2
    done
    for pid; do
        if _slurm_alive "$pid"; then
            _slurm_log "pid $pid still there after ${timeout}s of SIGTERM, sending SIGKILL"
            kill -KILL "$pid" 2> /dev/null || true
        fi
    done
    return 0
}

# _slurm_until TIMEOUT_S COMMAND...: runs COMMAND every 0.25 s until it succeeds (0) or TIMEOUT_S pass (1).
# Also gives up (1) as soon as a daemon started so far has died, so a broken configuration fails fast.
_slurm_until() {
    local deadline=$((SECONDS + $1)) entry
    shift
    while :; do
        "$@" && return 0
        for entry in "${_slurm_pids[@]}"; do
            if ! _slurm_alive "${entry#*:}"; then
                _slurm_log "${entry%%:*} (pid ${entry#*:}) died"
                return 1
            fi
        done
        [ "$SECONDS" -lt "$deadline" ] || return 1
        sleep 0.25
    done
}

# _slurm_pidfile NAME FILE: waits for a daemon's pid file, checks that the pid is this cluster's, records it.
_slurm_pidfile() {
    local name=$1 file=$2 pid=""
    _slurm_until 20 test -s "$file" || { _slurm_log "$name wrote no pid file $file"; return 1; }
    read -r pid < "$file" || true
    if ! [[ "$pid" =~ ^[0-9]+$ ]] || ! _slurm_ours "$pid"; then
        _slurm_log "$name: pid file $file names '$pid', which is not a live daemon of this cluster"
        return 1
    fi
    _slurm_pids+=("$name:$pid")
}

# _slurm_free_ports N: N distinct TCP ports that nothing listens on (any address), outside the ephemeral range
# (32768-60999 on Linux) so that an outgoing connection cannot take one between this check and the bind.
_slurm_free_ports() {
    python3 - "$1" << 'EOF'
import random, socket, sys
want, ports = int(sys.argv[1]), []
for _ in range(1000):
    if len(ports) == want:
        break
    port = random.randint(20000, 32000)
    if port in ports:
        continue
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        try:
            s.bind(("0.0.0.0", port))   # the daemons listen on every address
        except OSError:
            continue
    ports.append(port)
if len(ports) != want:
    sys.exit("no free ports found")
print(*ports)
EOF
}

_slurm_dump_logs() {
    local f
    for f in "$SLURM_CLUSTER_DIR"/log/*; do
        [ -f "$f" ] || continue
        echo "----- $f (last 40 lines)" >&2
        tail -n 40 "$f" >&2 || true
    done
}

_slurm_munge_ok() { munge -n -S "$SLURM_CLUSTER_DIR/munge/munge.socket" > /dev/null 2>&1; }
_slurm_ctld_ok() { timeout 10 scontrol ping 2> /dev/null | grep -q 'is UP'; }
_slurm_node_idle() {
    local state
    state=$(timeout 10 sinfo -h -n "$SLURM_CLUSTER_NODE" -o %T 2> /dev/null) || return 1
    [ "$state" = idle ]
}

# slurm_cluster_start DIR: writes a munge key and slurm.conf under DIR (created if needed), starts munged,
# slurmctld and slurmd, exports SLURM_CONF, and returns once the node is idle, within SLURM_CLUSTER_TIMEOUT
# seconds (60). On failure it prints the daemons' logs, stops what it started and returns 1.
slurm_cluster_start() {
    if [ $# -ne 1 ] || [ -z "$1" ]; then
        _slurm_log "usage: slurm_cluster_start DIR"
        return 2
    fi
    if [ -n "$SLURM_CLUSTER_DIR" ]; then
        _slurm_log "a cluster already runs in $SLURM_CLUSTER_DIR"
        return 1
    fi
    if [ "$(id -u)" -ne 0 ]; then
        _slurm_log "needs root: slurmd must be root to start jobs"
        return 1
    fi
    # The daemons live in sbin, which a non-login root shell (ctest, sudo -E) may not have on its PATH.
    local tool
    local -A bin=()
    for tool in munged mungekey slurmctld slurmd munge sbatch sinfo squeue scontrol scancel python3 timeout; do
        if ! bin[$tool]=$(PATH="$PATH:/usr/sbin:/sbin" command -v "$tool"); then
            _slurm_log "$tool not found: scripts/deps.sh installs slurm-wlm and munge"
            return 1
        fi
    done
    local dir
    dir=$(mkdir -p "$1" && cd "$1" && pwd -P) || { _slurm_log "cannot use $1 as the cluster's folder"; return 1; }

    local started=$SECONDS timeout=${SLURM_CLUSTER_TIMEOUT:-60}
    SLURM_CLUSTER_DIR=$dir
    SLURM_CLUSTER_NODE=$(hostname -s)
    _slurm_pids=()
    mkdir -p "$dir/munge" "$dir/log" "$dir/state" "$dir/spool" || { _slurm_cluster_failed; return 1; }

    # munge: a fresh key for this cluster only, 0400 and owned by root, the user munged runs as here. munged
    # refuses root and a socket folder that not everyone can enter (mktemp -d is 0700) unless forced.
    if ! "${bin[mungekey]}" --create --keyfile="$dir/munge/munge.key" > "$dir/log/mungekey.out" 2>&1 ||
        ! chmod 0400 "$dir/munge/munge.key"; then
        _slurm_log "could not create the munge key"
        _slurm_cluster_failed
        return 1
    fi
    if ! env "$_SLURM_MARK=$dir" timeout 20 "${bin[munged]}" --force \
        --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
        --pid-file="$dir/munge/munged.pid" --seed-file="$dir/munge/munged.seed" \
        --log-file="$dir/log/munged.log" < /dev/null > "$dir/log/munged.out" 2>&1 ||
        ! _slurm_pidfile munged "$dir/munge/munged.pid" ||
        ! _slurm_until 10 _slurm_munge_ok; then
        _slurm_log "munged did not start"
        _slurm_cluster_failed
        return 1
    fi

    local ports cpus mem
    ports=$(_slurm_free_ports 2) || { _slurm_log "no free TCP ports"; _slurm_cluster_failed; return 1; }
    cpus=$(nproc)
    # slurmd drains a node that has less memory than slurm.conf says; stay 10% under the total (what free -m
    # shows, read from /proc so that procps is not needed).
    mem=$(awk '/^MemTotal:/ { print int($2 / 1024 * 0.9) }' /proc/meminfo)
    _slurm_write_conf "$dir" "${ports% *}" "${ports#* }" "$cpus" "$mem" > "$dir/slurm.conf" ||
        { _slurm_cluster_failed; return 1; }
    # An empty plugin stack, so that no SPANK plugin of the host's /etc/slurm/plugstack.conf is loaded.
    : > "$dir/plugstack.conf"

    if [ "$_slurm_old_conf_set" -eq 0 ]; then
        _slurm_old_conf=${SLURM_CONF:-}
        [ -n "${SLURM_CONF+set}" ] && _slurm_old_conf_set=1 || _slurm_old_conf_set=2
    fi
    export SLURM_CONF="$dir/slurm.conf"

    # Both daemonise; their pid files give the pids to stop. timeout only bounds the part before they fork.
    if ! env "$_SLURM_MARK=$dir" timeout 30 "${bin[slurmctld]}" -f "$dir/slurm.conf" \
        < /dev/null > "$dir/log/slurmctld.out" 2>&1 ||
        ! _slurm_pidfile slurmctld "$dir/slurmctld.pid" ||
        ! _slurm_until "$timeout" _slurm_ctld_ok; then
        _slurm_log "slurmctld did not start"
        _slurm_cluster_failed
        return 1
    fi
    if ! env "$_SLURM_MARK=$dir" timeout 30 "${bin[slurmd]}" -f "$dir/slurm.conf" -N "$SLURM_CLUSTER_NODE" \
        < /dev/null > "$dir/log/slurmd.out" 2>&1 ||
        ! _slurm_pidfile slurmd "$dir/slurmd.pid"; then
        _slurm_log "slurmd did not start"
        _slurm_cluster_failed
        return 1
    fi
    local left=$((timeout - (SECONDS - started)))
    if [ "$left" -lt 1 ] || ! _slurm_until "$left" _slurm_node_idle; then
        _slurm_log "node $SLURM_CLUSTER_NODE not idle within ${timeout}s; sinfo says:"
        timeout 10 sinfo -N -l >&2 2>&1 || true
        _slurm_cluster_failed
        return 1
    fi

    _slurm_start_watchdog
    return 0
}

# _slurm_write_conf DIR CTLD_PORT SLURMD_PORT CPUS MEMORY_MB: slurm.conf on stdout.
_slurm_write_conf() {
    local dir=$1 node=$SLURM_CLUSTER_NODE
    cat << EOF
# Written by tests/e2e/slurm-cluster.bash for one test: a single node on localhost, every path under this folder.
ClusterName=photopic-e2e
# The address is given so that nothing depends on how this host's name resolves.
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$2
SlurmdPort=$3
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
MpiDefault=none
# No cgroups in a container: track job processes by parentage, bind nothing.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
# Cores, not whole nodes, are allocated: several 1-CPU jobs run at once.
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
# Schedule a batch job when it is submitted, not up to 3 s later: a test's jobs start at once.
SchedulerParameters=batch_sched_delay=0
# Finished jobs stay known to scontrol for an hour (no accounting, so no sacct): slurm_wait_jobs reads their states.
MinJobAge=3600
# A job whose dependency can never be met (afterok on a failed job) is cancelled instead of pending forever.
DependencyParameters=kill_invalid_depend
# scancel (and slurm_cluster_stop) gets from SIGTERM to SIGKILL in 5 s rather than 30.
KillWait=5
MailProg=/bin/true
PlugStackConfig=$dir/plugstack.conf
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
NodeName=$node NodeAddr=127.0.0.1 NodeHostname=$node CPUs=$4 RealMemory=$5 State=UNKNOWN
PartitionName=$SLURM_CLUSTER_PARTITION Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
}

_slurm_cluster_failed() {
    _slurm_dump_logs
    slurm_cluster_stop
}

# The watchdog: a detached subshell that stops the cluster when the shell that started it is gone without having
# called slurm_cluster_stop (killed by SIGKILL, say by a test runner's timeout), so that no daemon outlives the
# test. It holds none of the caller's output (a runner reading the test's pipe would wait for it).
_slurm_start_watchdog() {
    local owner=$BASHPID
    (
        trap - EXIT INT TERM
        while kill -0 "$owner" 2> /dev/null; do sleep 1; done
        _slurm_log "the shell that started the cluster in $SLURM_CLUSTER_DIR is gone; stopping it"
        slurm_cluster_stop
    ) < /dev/null > /dev/null 2>> "$SLURM_CLUSTER_DIR/log/watchdog.log" &
    _slurm_watchdog=$!
    disown "$_slurm_watchdog" 2> /dev/null || true
}

# slurm_cluster_stop: cancels the cluster's jobs, then stops slurmd, slurmctld and munged by the pids recorded
# at start (SIGTERM, 10 s, SIGKILL), then any step daemon of this cluster that outlived them, with the job
# processes under it. Restores the caller's SLURM_CONF. Idempotent, quiet when nothing runs, always returns 0:
# safe in an EXIT trap.
slurm_cluster_stop() {
    [ -n "$SLURM_CLUSTER_DIR" ] || return 0
    local entry pid ids
    if [ -n "$_slurm_watchdog" ]; then
        # shellcheck disable=SC2046 # a list of pids
        kill -TERM $(_slurm_with_descendants "$_slurm_watchdog") 2> /dev/null || true
        _slurm_watchdog=""
    fi

    # Jobs first, while slurmctld and slurmd can still end them: slurmstepd kills its job's processes.
    for entry in "${_slurm_pids[@]}"; do
        if [ "${entry%%:*}" = slurmctld ] && _slurm_ours "${entry#*:}"; then
            ids=$(SLURM_CONF="$SLURM_CLUSTER_DIR/slurm.conf" timeout 10 squeue -h -o %i 2> /dev/null || true)
            if [ -n "$ids" ]; then
                # shellcheck disable=SC2086 # a list of job ids
                SLURM_CONF="$SLURM_CLUSTER_DIR/slurm.conf" timeout 10 scancel $ids 2> /dev/null || true
                local deadline=$((SECONDS + 10))
                while [ "$SECONDS" -lt "$deadline" ] &&
                    [ -n "$(SLURM_CONF="$SLURM_CLUSTER_DIR/slurm.conf" timeout 5 squeue -h -o %i 2> /dev/null)" ]; do
                    sleep 0.5
                done
            fi
        fi
    done

    # The daemons, in the reverse order of their start: munged last, slurmd and slurmctld need it to part.
    local i
    for ((i = ${#_slurm_pids[@]} - 1; i >= 0; i--)); do
        pid=${_slurm_pids[i]#*:}
        if _slurm_ours "$pid"; then
            _slurm_terminate 10 "$pid"
        fi
    done
    _slurm_pids=()

    # Stray step daemons (slurmd does not take them down with it) and what still runs under them.
    local strays
    strays=$(_slurm_marked)
    if [ -n "$strays" ]; then
        # shellcheck disable=SC2086 # a list of pids
        strays=$(_slurm_with_descendants $strays)
        _slurm_log "stopping leftover processes of the cluster: ${strays//$'\n'/ }"
        # shellcheck disable=SC2086
        _slurm_terminate 5 $strays
    fi

    case "$_slurm_old_conf_set" in
        1) export SLURM_CONF="$_slurm_old_conf" ;;
        2) unset SLURM_CONF ;;
    esac
    _slurm_old_conf_set=0
    SLURM_CLUSTER_DIR=""
    SLURM_CLUSTER_NODE=""
    return 0
}

# slurm_wait_jobs [-t TIMEOUT_S] JOBID...: waits until every given job (every task of an array job) has left the
# queue, for at most TIMEOUT_S seconds (default SLURM_WAIT_TIMEOUT, else 300). Returns 0 if all ended COMPLETED;
# otherwise prints the failed or unfinished ones (state, reason, exit code, the end of their output) and returns 1.
# The timeout is an option, not a trailing argument, because job ids and seconds are both bare numbers.
# Final states come from scontrol, which remembers finished jobs for MinJobAge (there is no accounting for sacct).
slurm_wait_jobs() {
    local timeout=${SLURM_WAIT_TIMEOUT:-300}
    if [ "${1:-}" = -t ]; then
        timeout=${2:-}
        shift 2 || true
    fi
    if ! [[ "$timeout" =~ ^[0-9]+$ ]] || [ $# -eq 0 ]; then
        _slurm_log "usage: slurm_wait_jobs [-t TIMEOUT_S] JOBID..."
        return 2
    fi
    local deadline=$((SECONDS + timeout)) id out rec state waiting
    local -a bad unfinished
    while :; do
        waiting=0
        bad=()
        unfinished=()
        for id in "$@"; do
            id=${id%%;*} # sbatch --parsable prints ID;CLUSTER on multi-cluster setups
            if ! out=$(timeout 15 scontrol -o show job "$id" 2>&1); then
                if [[ "$out" == *"Invalid job id"* ]]; then
                    bad+=("JobId=$id unknown to slurmctld")
                else
                    waiting=1 # slurmctld busy or slow to answer: ask again
                    unfinished+=("JobId=$id scontrol: $out")
                fi
                continue
            fi
            while IFS= read -r rec; do
                [ -n "$rec" ] || continue
                state=$(_slurm_field JobState "$rec")
                case "$state" in
                    COMPLETED) ;;
                    CANCELLED | FAILED | TIMEOUT | NODE_FAIL | PREEMPTED | BOOT_FAIL | DEADLINE | OUT_OF_MEMORY)
                        bad+=("$rec") ;;
                    *) # PENDING, RUNNING, COMPLETING, CONFIGURING, SUSPENDED, REQUEUED...
                        waiting=1
                        unfinished+=("$rec") ;;
                esac
            done <<< "$out"
        done
        [ "$waiting" -eq 1 ] || break
        if [ "$SECONDS" -ge "$deadline" ]; then
            _slurm_log "jobs $* still in the queue after ${timeout}s:"
            for rec in "${unfinished[@]}"; do _slurm_describe_job "$rec"; done
            for rec in "${bad[@]}"; do _slurm_describe_job "$rec"; done
            return 1
        fi
        sleep 0.5
    done
    [ ${#bad[@]} -eq 0 ] && return 0
    _slurm_log "jobs that did not complete:"
    for rec in "${bad[@]}"; do _slurm_describe_job "$rec"; done
    return 1
}

# _slurm_field NAME RECORD: the value of NAME=value in a one-line scontrol record.
_slurm_field() {
    local re="(^| )$1=([^ ]*)"
    [[ "$2" =~ $re ]] && echo "${BASH_REMATCH[2]}"
    return 0
}

_slurm_describe_job() {
    local rec=$1 name task out err f
    if [[ "$rec" != *JobState=* ]]; then
        echo "    $rec" >&2
        return 0
    fi
    name=$(_slurm_field JobId "$rec")
    task=$(_slurm_field ArrayTaskId "$rec")
    [ -n "$task" ] && name="$(_slurm_field ArrayJobId "$rec")_$task"
    echo "    job $name ($(_slurm_field JobName "$rec")): $(_slurm_field JobState "$rec")," \
        "reason $(_slurm_field Reason "$rec"), exit code $(_slurm_field ExitCode "$rec")" >&2
    out=$(_slurm_field StdOut "$rec")
    err=$(_slurm_field StdErr "$rec")
    [ "$err" = "$out" ] && err=""
    for f in "$out" "$err"; do
        if [ -f "$f" ] && [ -s "$f" ]; then
            echo "      $f (last 10 lines):" >&2
            tail -n 10 "$f" | sed 's/^/        /' >&2 || true
        fi
    done
    return 0
}

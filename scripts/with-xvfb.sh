#!/usr/bin/env bash
# with-xvfb.sh COMMAND [ARGS...]: runs a windowed program on a private virtual X server (no screen needed)
# and exits with its status.
set -uo pipefail
source "$(dirname "$0")/xvfb.bash"
dir="$(mktemp -d "${TMPDIR:-/tmp}/photopic-xvfb.XXXXXX")"
start_xvfb "$dir" || exit 1
"$@"
status=$?
kill "$XVFB_PID" 2> /dev/null
rm -rf "$dir"
exit $status

# start_xvfb DIR: starts a private Xvfb server for this shell, exports DISPLAY, and kills the server on exit.
# Xvfb picks a free display itself and writes its number to fd 3 (-displayfd), so parallel jobs never race
# for a display number (xvfb-run -a did, and its clean-up failed under load). DIR keeps the server's log.
# Sourced (named .bash); scripts/deps.sh installs xvfb and xauth.
start_xvfb() {
    local dir="$1"
    if ! command -v Xvfb > /dev/null; then
        echo "FAIL: Xvfb is missing; run scripts/deps.sh (installs xvfb and xauth)"
        return 1
    fi
    exec 3> "$dir/display"
    Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp > "$dir/xvfb.log" 2>&1 &
    XVFB_PID=$!
    exec 3>&-
    trap 'kill "$XVFB_PID" 2> /dev/null' EXIT
    for _ in $(seq 100); do
        [ -s "$dir/display" ] && break
        sleep 0.1
    done
    if [ ! -s "$dir/display" ]; then
        echo "FAIL: Xvfb did not start"
        cat "$dir/xvfb.log"
        return 1
    fi
    export DISPLAY=":$(head -n 1 "$dir/display")"
}

# Helpers sourced by the e2e scripts (named .bash so the *.sh glob does not run it as a test).
PHOTOPIC="$1"
DATA="$2"
SCRATCH="$3"
rm -rf "$SCRATCH" && mkdir -p "$SCRATCH"
failures=0
checks=0

# expect CODE DESCRIPTION -- command...: runs the command, checks its exit code, keeps stdout+stderr in $OUTPUT.
expect() {
    local want="$1" what="$2"
    shift 3
    checks=$((checks + 1))
    OUTPUT=$("$@" 2>&1)
    local got=$?
    if [ "$got" -ne "$want" ]; then
        echo "FAIL: $what: exit $got, wanted $want"
        echo "$OUTPUT" | sed 's/^/    /' | head -20
        failures=$((failures + 1))
        return 1
    fi
    echo "ok: $what"
}

# check DESCRIPTION CONDITION...: a plain assertion.
check() {
    local what="$1"
    shift
    checks=$((checks + 1))
    if "$@"; then
        echo "ok: $what"
    else
        echo "FAIL: $what"
        failures=$((failures + 1))
    fi
}

contains() { [[ "$OUTPUT" == *"$1"* ]]; }

finish() {
    echo "$((checks - failures)) passed, $failures failed"
    [ "$failures" -eq 0 ]
}

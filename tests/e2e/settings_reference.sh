#!/usr/bin/env bash
# docs/settings.md is what `photopic settings --markdown` prints: the committed reference of every setting
# stays current with the settings reflection (a field added, a range or description changed).
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
DOC="$(dirname "$0")/../../docs/settings.md"

expect 0 "photopic settings --markdown" -- "$PHOTOPIC" settings --markdown
"$PHOTOPIC" settings --markdown > "$S/settings.md" 2> /dev/null
check "lists post settings with type, default, range and meaning" \
    grep -q '^| `bloom.intensity` | number | `0.04` | \[0, 10\] | .\+ |$' "$S/settings.md"
check "lists each built-in scene's settings" grep -q '^| `testbed.fNumber` | number |' "$S/settings.md"
check "lists what each preset changes" grep -q '^### stills$' "$S/settings.md"
check "no field lacks a meaning (every field() has a description)" bash -c \
    "! grep -E '^\| \`[^|]+\` \|[^|]+\|[^|]+\|[^|]*\|\s*\|$' '$S/settings.md'"
if ! diff -u "$DOC" "$S/settings.md" > "$S/settings.diff"; then
    echo "FAIL: docs/settings.md is stale: it differs from \`photopic settings --markdown\`."
    echo "    Regenerate it: make settings-doc (or build/release/photopic settings --markdown > docs/settings.md)"
    head -40 "$S/settings.diff" | sed 's/^/    /'
    failures=$((failures + 1))
fi
checks=$((checks + 1))
expect 2 "--markdown with --preset is refused" -- "$PHOTOPIC" settings --markdown --preset stills
check "says why" contains "--markdown lists every preset"

finish

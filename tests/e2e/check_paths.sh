#!/usr/bin/env bash
# scripts/check-paths.py: this repository's docs and comments name only paths that exist (make test runs it),
# and a path that does not exist is found and named, in prose and in a comment, not in code.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
CHECK="$ROOT/scripts/check-paths.py"
lacks() { [[ "$OUTPUT" != *"$1"* ]]; }

expect 0 "the repository's paths all exist" -- bash -c "cd '$ROOT' && '$CHECK'"

mkdir -p "$S/repo/docs" "$S/repo/src"
cd "$S/repo" || exit 1
git init -q .
printf '# A\n\nSee docs/guide.md.\n' > README.md
printf 'As [the guide](guide.md) says.\n' > docs/other.md
printf 'The design: docs/nowhere.md, and src/a.cpp.\n' > docs/guide.md
printf '// Reads src/missing.h.\nconst char* kPattern = "src/frame_%%04d.exr"; // a pattern: src/f%%04d.exr\n' > src/a.cpp
printf 'cp src/notthere.txt out/  # code, not prose\n' > run.sh
git add -A
expect 1 "a named path that does not exist" -- "$CHECK"
check "names the doc's path with file and line" contains "missing: docs/guide.md:1 docs/nowhere.md"
check "names the comment's path" contains "missing: src/a.cpp:1 src/missing.h"
check "a relative Markdown link resolves from its folder" lacks "docs/other.md"
check "patterns and code are left alone" lacks "frame_"
check "code is not prose" lacks "notthere"

finish

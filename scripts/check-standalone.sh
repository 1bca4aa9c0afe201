#!/usr/bin/env bash
# Fails when a file of the repository names the folder that sits beside the repository on the development machines
# (dot-dot, slash, "shared"): a user's clone has nothing beside it, so such a path breaks the build, the tests or
# the docs there. In a git checkout it checks the tracked files plus new files git does not ignore; elsewhere (an
# unpacked tarball, a copy) every file outside build/, out/ and .git/.
set -euo pipefail
cd "$(dirname "$0")/.."

# Built in two pieces so this script does not name the path it looks for.
pattern='\.\./sha''red'

if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    list() { git ls-files -z --cached --others --exclude-standard; }
else
    list() { find . \( -path ./build -o -path ./out -o -path ./.git \) -prune -o -type f -print0; }
fi

matches=$(list | xargs -0 -r sh -c 'for f; do [ -f "$f" ] && printf "%s\0" "$f"; done' sh |
    xargs -0 -r grep -n -e "$pattern" -- || true)
if [ -n "$matches" ]; then
    echo "check-standalone: these lines name a folder outside the repository:"
    echo "$matches" | sed 's/^/    /'
    exit 1
fi
echo "check-standalone: no file names a folder outside the repository"

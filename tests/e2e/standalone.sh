#!/usr/bin/env bash
# A copy of the repository stands alone: its files (tracked, plus new ones git does not ignore; no build folders)
# are copied into a temporary folder that has nothing beside it, and with PHOTOPIC_DATA_DIR unset
#   - the copy names no folder outside itself (scripts/check-standalone.sh, its non-git branch),
#   - `photopic demo --images` run inside the copy finds the copy's data/ by itself (the checkout step of
#     photopic::findDataDir), not this checkout's,
#   - the io tests and the other e2e scripts pass on the copy's files. The viewer script is left out: it reads no
#     file of the repository (built-in scenes only), and a second Xvfb server beside e2e.viewer's only doubles the
#     exposure to xvfb-run's race when it removes its temporary folder (exit 5, seen under load). So are the two
#     Slurm scripts (farm, slurm_smoke): they read no file of the repository either, and a second Slurm cluster
#     beside theirs would only race them for the node's CPUs.
# It builds nothing: it runs this build's binaries, which is what a fresh clone's build would produce from the same
# sources. A full build-and-test of a clone is too slow for every `make test`; the README says how to run one.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
BUILD="$(dirname "$PHOTOPIC")"
TMP="$(mktemp -d "${TMPDIR:-/tmp}/photopic-standalone.XXXXXX")"
trap 'rm -rf "$TMP"' EXIT
COPY="$TMP/photopic"
mkdir -p "$COPY"
unset PHOTOPIC_DATA_DIR

if git -C "$ROOT" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    (cd "$ROOT" && git ls-files -z --cached --others --exclude-standard |
        xargs -0 -r sh -c 'for f; do [ -f "$f" ] && printf "%s\0" "$f"; done' sh | tar --null -T - -cf -) |
        tar -C "$COPY" -xf -
else
    tar -C "$ROOT" --exclude=./build --exclude=./out -cf - . | tar -C "$COPY" -xf -
fi
check "copy made" test -s "$COPY/CMakeLists.txt" -a -s "$COPY/data/SOURCES.md"
check "nothing named shared beside the copy" test ! -e "$TMP/shared"
check "no build folder copied" test ! -e "$COPY/build"

cd "$COPY" || exit 1
expect 0 "the copy names no folder outside itself" -- bash scripts/check-standalone.sh

cd "$COPY/tests" || exit 1
expect 0 "demo --images without --data, inside the copy" -- "$PHOTOPIC" demo --images -o "$S/images"
check "it read the copy's data/" contains "reading 4 images from $COPY/data"

cd "$COPY" || exit 1
if [ -x "$BUILD/tests/photopic_io_tests" ]; then
    expect 0 "io tests on the copy's data" -- "$BUILD/tests/photopic_io_tests" --gtest_brief=1
fi
for script in "$COPY"/tests/e2e/*.sh; do
    name="$(basename "$script" .sh)"
    case "$name" in standalone | install | viewer | farm | slurm_smoke) continue ;; esac
    expect 0 "e2e $name on the copy" -- bash "$script" "$PHOTOPIC" "$COPY/data" "$TMP/scratch/$name"
done

finish

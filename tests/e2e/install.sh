#!/usr/bin/env bash
# The installed tree stands alone: `cmake --install` into a scratch prefix, then `photopic demo --images` with no
# other argument, from a folder outside the repository and with PHOTOPIC_DATA_DIR unset, finds the images that the
# install put under share/photopic/data beside the binary.
source "$(dirname "$0")/lib.bash"
S="$SCRATCH"
BUILD="$(dirname "$PHOTOPIC")"
PREFIX="$S/install"
ELSEWHERE="$(mktemp -d "${TMPDIR:-/tmp}/photopic-install-e2e.XXXXXX")"
trap 'rm -rf "$ELSEWHERE"' EXIT

expect 0 "cmake --install into a scratch prefix" -- cmake --install "$BUILD" --prefix "$PREFIX"
check "images installed under share/photopic/data" test -s "$PREFIX/share/photopic/data/Desk.exr"
check "their SOURCES.md and licence texts installed" \
    test -s "$PREFIX/share/photopic/data/SOURCES.md" -a -s "$PREFIX/share/photopic/LICENSES/CC-BY-4.0.txt"

cd "$ELSEWHERE" || exit 1
expect 0 "installed demo --images, no other argument, outside the repository" -- \
    env -u PHOTOPIC_DATA_DIR "$PREFIX/bin/photopic" demo --images
check "read the installed images" contains "reading 4 images from $PREFIX/share/photopic/data"
check "contact sheet written into ./out/demo" test -s "$ELSEWHERE/out/demo/contact_sheet.png"

expect 0 "PHOTOPIC_DATA_DIR still wins over the installed folder" -- \
    env PHOTOPIC_DATA_DIR="$DATA" "$PREFIX/bin/photopic" demo --images -o "$S/env"
check "read PHOTOPIC_DATA_DIR" contains "from $DATA"
expect 2 "a data folder that does not exist is named" -- \
    env PHOTOPIC_DATA_DIR="$S/nowhere" "$PREFIX/bin/photopic" demo --images -o "$S/nowhere-out"
check "error names the folder" contains "$S/nowhere"

finish

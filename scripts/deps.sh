#!/usr/bin/env bash
# Installs the Debian 12 packages Photopic needs, and only those that are missing.
# Idempotent: prints one line and does nothing when everything is present. Uses sudo only when not root.
set -euo pipefail

packages=(
    build-essential cmake pkg-config clang-format
    libepoxy-dev libegl-dev libgl1-mesa-dri libegl-mesa0
    libopenexr-dev libpng-dev libdeflate-dev libtiff-dev libstb-dev libopencolorio-dev
    nlohmann-json3-dev libtinygltf-dev libcli11-dev libfmt-dev libglm-dev
    libglfw3-dev libimgui-dev xvfb xauth
    libopengl-dev libgl-dev python3-glad doxygen
    libgtest-dev libgmock-dev libbenchmark-dev
    slurm-wlm munge
    blender
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "deps: all ${#packages[@]} packages present"
    exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
fi
echo "deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs osgVis's build, test and run dependencies from Debian 12 packages (run as root).
# Skips apt entirely when everything is already there, so repeated runs are quick.
set -euo pipefail
packages=(
    build-essential cmake pkg-config
    libopenscenegraph-dev openscenegraph
    libglfw3-dev libglm-dev libopenmesh-dev libtinygltf-dev libtbb-dev libembree-dev
    libgtest-dev libgmock-dev libbenchmark-dev libcgal-dev libgmp-dev libmpfr-dev libopenmpi-dev openmpi-bin
    assimp-testmodels doxygen chromium openarena-081-maps openarena-088-data unzip
    xvfb xauth x11-utils libgl1-mesa-dri mesa-utils
)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "deps: all ${#packages[@]} packages present"
    exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
    echo "deps: missing packages: ${missing[*]}; run as root (or install them) first" >&2
    exit 1
fi
echo "deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start #1: installs dependencies, builds, generates the demo scene (an office floor) and
# runs the walkthrough on it. With no display it renders headless under Xvfb and writes the
# screenshots and report to out/demo/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${OSGVIS_BUILD_DIR:-$root/build}
out=${OSGVIS_DEMO_DIR:-$root/out/demo}
bash "$root/scripts/deps.sh"
OSGVIS_BUILD_DIR=$build bash "$root/scripts/build.sh"
export OSG_LIBRARY_PATH=$build/lib
mkdir -p "$out"
"$build/bin/osgvisgen" --kind office --triangles 200000 --seed 1 -o "$out/office.osgb"
if [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1 && [ -z "${OSGVIS_HEADLESS:-}" ]; then
    exec "$build/bin/osgvisviewer" "$out/office.osgb" --mode frustum
fi
bash "$root/scripts/with-display.sh" "$build/bin/osgvisviewer" "$out/office.osgb" --mode frustum \
    --headless "$out" --size 640x512
echo "demo: screenshots and report in $out (report.txt)"
cat "$out/report.txt" 2>/dev/null || true

#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start #1: what osgVis does, on a generated office floor or on your own model.
#   scripts/demo.sh [MODEL]     (MODEL: any file OpenSceneGraph reads; default: a generated office)
# Installs dependencies and builds, then renders the same walk with plain OSG and with every culling
# mode against the exact-visibility oracle (osgvisbench), and writes to out/demo/:
#   index.html        the report: table, per-view plots of drawn triangles and cull time
#   view-NNNN.png     side by side: plain OSG | the best mode | top-down map of what it drew and culled
#   report.txt        the table, with the best mode's ratios against plain OSG
# With a display it then opens the walkthrough viewer on the best mode (keys named in the window).
# OSGVIS_DEMO_VIEWS (default 60) views at OSGVIS_DEMO_SIZE (default 640x512); OSGVIS_HEADLESS=1
# never opens a window.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${OSGVIS_BUILD_DIR:-$root/build}
out=${OSGVIS_DEMO_DIR:-$root/out/demo}
views=${OSGVIS_DEMO_VIEWS:-60}
size=${OSGVIS_DEMO_SIZE:-640x512}
model=${1:-}
if [ -n "$model" ] && [ ! -f "$model" ]; then
    echo "demo: no such model file: $model" >&2
    exit 2
fi
bash "$root/scripts/deps.sh"
OSGVIS_BUILD_DIR=$build bash "$root/scripts/build.sh" >/dev/null
export OSG_LIBRARY_PATH=$build/lib
mkdir -p "$out"
if [ -z "$model" ]; then
    model=$out/office.osgb
    "$build/bin/osgvisgen" --kind office --triangles 200000 --seed 1 -o "$model"
fi

echo "demo: measuring every mode against the oracle on $model ($views views at $size)..."
bash "$root/scripts/with-display.sh" "$build/bin/osgvisbench" --scene "$model" \
    --modes osg,frustum,octree,mask,exact --views "$views" --size "$size" \
    --report "$out" --pictures 6 --json "$out/bench.json" | tee "$out/report.txt"
best=$(sed -n 's/^best mode: \([^ ]*\) vs .*/\1/p' "$out/report.txt")

echo
echo "demo: report  $out/index.html"
echo "demo: pictures $(ls "$out"/view-*.png 2>/dev/null | tr '\n' ' ')"
grep '^best mode:' "$out/report.txt" || echo "demo: no culling mode beat plain OSG here: frustum is the mode for this model"
if [ -n "$best" ] && [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1 && [ -z "${OSGVIS_HEADLESS:-}" ]; then
    echo "demo: opening the viewer on $best (m: next mode, t: map, i: statistics, h: help)"
    exec "$build/bin/osgvisviewer" "$model" --mode "$best"
fi

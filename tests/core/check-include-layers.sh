#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The layer check of scripts/core-include-graph.sh: our core passes it, and a copy of the core with
# a method including another method and a lower layer including a higher one fails it, naming both.
set -euo pipefail
source_dir=$1
script=$source_dir/scripts/core-include-graph.sh
bash "$script" | tee /dev/stderr | grep -q '^include layers: ok'

tree=$(mktemp -d)
trap 'rm -rf "$tree"' EXIT
cp -r "$source_dir/osgvis/core/include" "$source_dir/osgvis/core/src" "$tree/"
echo '#include <osgVis/core/mask/OcclusionMask.h>' >> "$tree/src/octree/OcclusionTree.h"
echo '#include <osgVis/core/module/VisibilityModule.h>' >> "$tree/include/osgVis/core/scene/Walk.h"
status=0
out=$(bash "$script" --root "$tree") || status=$?
echo "$out"
[ "$status" -eq 1 ] || { echo "expected exit 1 on the broken tree, got $status"; exit 1; }
grep -q '^VIOLATION: octree -> mask (between two methods)' <<<"$out"
grep -q '^VIOLATION: scene -> module (upwards)' <<<"$out"
grep -q '^include layers: VIOLATED' <<<"$out"
echo "check-include-layers: ok"

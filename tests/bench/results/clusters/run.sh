#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Clusters (issue 22, docs/clusters.md): the Khronos 2CylinderEngine (its default walk from inside,
# 100 views) with clusters off, at the default threshold (4096) and at 1024, side by side; the
# generated city 500k with clusters off and at 1024; extraction time and memory of a generated
# 2M-triangle forest. Run by hand from the repository root after a RelWithDebInfo build in build/;
# writes the JSON and text here. The exact commands the committed files came from.
set -euo pipefail
out=$(cd "$(dirname "$0")" && pwd)
bin=${OSGVIS_BIN:-build/bin}
export OSG_LIBRARY_PATH=${OSG_LIBRARY_PATH:-$PWD/build/lib}
engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
for clusters in off on 1024; do
    bash scripts/with-display.sh "$bin/osgvisbench" --scene "$engine" --views 100 \
        --modes osg,frustum,octree,mask,cdt --clusters "$clusters" --json "$out/engine-clusters-$clusters.json" \
        > "$out/engine-clusters-$clusters.txt" 2>&1
done
for clusters in off 1024; do
    bash scripts/with-display.sh "$bin/osgvisbench" --generate city --triangles 500000 --views 100 \
        --modes osg,frustum,octree,mask --clusters "$clusters" --json "$out/city-clusters-$clusters.json" \
        > "$out/city-clusters-$clusters.txt" 2>&1
done
for clusters in off on; do
    bash scripts/with-display.sh "$bin/osgvisbench" --generate office --triangles 500000 --views 100 \
        --modes osg,frustum,octree,mask --clusters "$clusters" --json "$out/office-clusters-$clusters.json" \
        > "$out/office-clusters-$clusters.txt" 2>&1
done
scene=$(mktemp -d)/forest2m.osgb # generated, never committed
"$bin/osgvisgen" --kind forest --triangles 2000000 -o "$scene"
for threshold in 4096 1024; do
    OSGVIS_CLUSTER_THRESHOLD=$threshold "$bin/osgvis_cluster_extraction_time" "$scene" 3
done > "$out/extraction-forest2m.txt"

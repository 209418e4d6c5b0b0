#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The CDT method's acceptance runs (issue 21): the three generated 500k scenes side by side with
# octree and mask, and the efficacy against the constraint budget on tetra 500k. Run by hand from
# the repository root after a RelWithDebInfo build (slow on llvmpipe); writes the JSON and text here.
set -euo pipefail
out=$(cd "$(dirname "$0")" && pwd)
bench=${OSGVIS_BENCH:-build/bin/osgvisbench}
export LP_NUM_THREADS=1
for scene in tetra office city; do
    bash scripts/with-display.sh "$bench" --generate "$scene" --triangles 500000 --views 60 \
        --modes osg,octree,mask,cdt,cdt-depthfree,cdt-depth,exact --json "$out/$scene-500k.json" \
        > "$out/$scene-500k.txt"
done
for budget in 512 2048 8192 32768 0; do
    bash scripts/with-display.sh "$bench" --generate tetra --triangles 500000 \
        --views 60 --modes "osg,cdt:constraintBudget=$budget" --json "$out/tetra-500k-budget-$budget.json" > "$out/tetra-500k-budget-$budget.txt"
done
# The cull walking a renderer's hierarchy beside the module's own kd-tree (issue 24, ordered
# traversal by callback): the test city, 30 street views, repetitions interleaved.
build/bin/osgvis_cdt_microbench --benchmark_filter=CdtCullCity --benchmark_repetitions=5 \
    --benchmark_enable_random_interleaving=true --benchmark_out="$out/hierarchy.json" --benchmark_out_format=json \
    > "$out/hierarchy.txt"
